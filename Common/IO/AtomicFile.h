// Every file the apps write goes through here: written whole to a temporary sibling in the destination's own
// folder, flushed to the disk and checked (each write, fsync, close), then renamed into place, so that a full
// disk, a failed writer or Ctrl-C never leaves a half-written file behind and never reports one as written. A
// destination that exists must be a regular file (a symbolic link to one is followed, keeping the link):
// renaming over a device, a folder, a pipe or a socket would replace it, and is refused.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace rt
{
/// Runs `write` on a temporary sibling of outputTarget(`path`), flushes it to the disk (fsync, checked) and
/// renames it over that target only if `write` returned true and the flush held, so a failed, cancelled or
/// crashed write never leaves a half-written file behind. Throws OutputError naming `path` and, where the C
/// library gave one, the reason (missing folder, not a regular file, write, flush or rename failure).
void writeAtomically(const std::filesystem::path& path, const std::function<bool(const std::filesystem::path&)>& write);

/// Why `path` cannot be replaced by a written file, or "" when it can: it (or, for a symbolic link, what the
/// link points to, followed to its end) exists and is not a regular file, or the link points nowhere.
/// `target` receives where the file must land (the link's target, else `path`).
std::string outputTargetProblem(const std::filesystem::path& path, std::filesystem::path& target);

/// Where writing `path` must land: the file a symbolic link points to (followed to its end), so that the
/// rename of writeAtomically and OutputSet replaces the target and keeps the link; `path` itself otherwise.
/// Throws OutputError ("cannot write 'path': ...") where outputTargetProblem names a problem.
std::filesystem::path outputTarget(const std::filesystem::path& path);

/// `path` as one spelling of its file: absolute, then weakly_canonical (which leaves a relative path relative where
/// its first part does not exist: a new "./y.exr" and "y.exr" would differ). `ec` set where that fails.
std::filesystem::path resolvedPath(const std::filesystem::path& path, std::error_code& ec);

/// `message`, a writer's error about `temporary`, naming `shown`, the file the user named, instead.
std::string namingShownFile(std::string message, const std::filesystem::path& temporary,
                            const std::filesystem::path& shown);

/// The most a file's temporaries lengthen its name (an OutputSet's temporary, written through writeAtomically's):
/// checkWritable probes a name this much longer than the output's.
inline constexpr std::size_t kTemporaryNameRoom = 40;

/// Creates an empty file beside `path` named `path` + `suffix` + the process's and a counter's numbers in hex, no
/// file there having that name, exclusively (a file or
/// a symbolic link already at a name is never followed, opened or replaced: another name is taken), with the
/// permissions a new file gets (0666 less the umask), and returns its name: the temporary a writer then fills.
/// Throws OutputError naming `path` where none can be created.
std::filesystem::path createTemporarySibling(const std::filesystem::path& path, const char* suffix);

/// Writes `bytes` to `file` (created or truncated; never through a symbolic link) and closes it, checking every
/// write and the close. Returns false with errno set on a failure (a full disk: ENOSPC; a file size limit: EFBIG).
bool writeBytes(const std::filesystem::path& file, std::string_view bytes);

/// writeAtomically for a text or binary blob.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);
} // namespace rt
