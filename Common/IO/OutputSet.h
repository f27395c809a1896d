// Files written as one set, all or none: a render's outputs (--output, --hdr, --stats), a scene export and its
// images. Each file alone was already atomic (IO/AtomicFile.h), but a stats file that failed after the PNG was
// written left the PNG behind with a failure status. Writable paths are checked before the render (checkWritable), so a
// failure here is rare: a full disk, a folder removed meanwhile.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace rt
{
/// Throws OutputError (naming `flag` and `path`) unless a file can be created at `path` now: `path` is not a
/// folder, nor anything but a regular file, nor a symbolic link to one or to nothing (outputTargetProblem), and
/// the folder it lands in exists and takes a new file (tried with a probe file, removed at once: permission
/// bits say nothing for root, nor for /proc or a read-only mount).
void checkWritable(const std::filesystem::path& path, const char* flag);

class OutputSet
{
public:
    /// `write(tmp)` writes the file to `tmp`, a sibling of `path`, throwing rt::Error on failure.
    using Writer = std::function<void(const std::filesystem::path& tmp)>;

    /// Throws OutputError where `path` lands on the file another entry writes (two flags naming one file: the
    /// second would replace the first, and a failure of either would remove the file both name).
    void add(std::filesystem::path path, Writer write);

    /// Writes every file to a new sibling `<path>.~pP-N` (createTemporarySibling), then renames each over its
    /// path. On a failure removes every temporary and every file this call already put in place, and rethrows: no
    /// output of the set is left behind (a file the set replaced is gone then; its old contents are not restored).
    void commit();

private:
    struct Entry
    {
        std::filesystem::path path;
        Writer write;
        std::filesystem::path pending; // its temporary, once created
    };
    std::vector<Entry> m_entries;
};
} // namespace rt
