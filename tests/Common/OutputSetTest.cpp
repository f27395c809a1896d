// IO/OutputSet: a render's outputs are written all or none, a failure names the user's file and its reason,
// a symbolic link is written through, and a path that cannot be written is found before the render (issue 13:
// a stats path that was a folder failed after the PNG was written).
#include <gtest/gtest.h>
#include <spdlog/fmt/fmt.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>

#include "Error.h"
#include "IO/AtomicFile.h"
#include "IO/OutputSet.h"
#include "Support/FileContents.h"
#include "Support/ScratchDir.h"

namespace rt
{
namespace
{
std::size_t filesIn(const std::filesystem::path& folder)
{
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder))
        ++n;
    return n;
}

TEST(OutputSet, WritesEveryFile)
{
    const test::ScratchDir dir;
    OutputSet set;
    for (const char* name : {"a.png", "a.pfm", "a.json"})
        set.add(dir / name, [name](const std::filesystem::path& tmp) { writeFileAtomically(tmp, name); });
    set.commit();
    EXPECT_EQ(filesIn(dir.path()), 3u); // no temporary left
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "a.json"));
}

TEST(OutputSet, TwoEntriesOfOneFileAreRefusedBeforeAnyIsWritten)
{
    // The same path, or a symbolic link to it: the second would replace the first, and a failure of either removed
    // the file both name (a user's x.exr given as --hdr and --heatmap was deleted).
    const test::ScratchDir dir;
    writeFileAtomically(dir / "x.exr", "keep");
    std::filesystem::create_symlink(dir / "x.exr", dir / "link.exr");
    for (const char* second : {"x.exr", "link.exr"})
    {
        OutputSet set;
        set.add(dir / "x.exr", [](const std::filesystem::path& tmp) { writeFileAtomically(tmp, "a"); });
        EXPECT_THROW(set.add(dir / second, [](const std::filesystem::path& tmp) { writeFileAtomically(tmp, "b"); }),
                     OutputError)
            << second;
    }
    EXPECT_EQ(test::fileContents(dir / "x.exr"), "keep");
    // A new file spelled two ways (weakly_canonical leaves a relative path whose first part does not exist as it is).
    const std::filesystem::path cwd = std::filesystem::current_path();
    std::filesystem::current_path(dir.path());
    OutputSet set;
    set.add("new.exr", [](const std::filesystem::path& tmp) { writeFileAtomically(tmp, "a"); });
    EXPECT_THROW(set.add("./new.exr", [](const std::filesystem::path& tmp) { writeFileAtomically(tmp, "b"); }),
                 OutputError);
    EXPECT_THROW(set.add(dir / "new.exr", [](const std::filesystem::path& tmp) { writeFileAtomically(tmp, "b"); }),
                 OutputError);
    std::filesystem::current_path(cwd);
}

TEST(OutputSet, ATemporarysNameTakenByAFileOrALinkIsLeftAlone)
{
    // A link at the name the temporary of before took (`<path>.pending`, fixed) had the file written through it
    // into its target; a user's file of that name was consumed. Each temporary is now created exclusively under a
    // name of its own.
    const test::ScratchDir dir;
    writeFileAtomically(dir / "victim.txt", "victim");
    std::filesystem::create_symlink(dir / "victim.txt", dir / "a.png.pending");
    writeFileAtomically(dir / "b.json.pending", "a user's file");
    OutputSet set;
    set.add(dir / "a.png", [](const std::filesystem::path& tmp) { writeFileAtomically(tmp, "png"); });
    set.add(dir / "b.json", [](const std::filesystem::path& tmp) { writeFileAtomically(tmp, "{}"); });
    set.commit();
    EXPECT_EQ(test::fileContents(dir / "victim.txt"), "victim");
    EXPECT_EQ(test::fileContents(dir / "b.json.pending"), "a user's file");
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "a.png.pending"));
    EXPECT_EQ(test::fileContents(dir / "a.png"), "png");
    EXPECT_FALSE(std::filesystem::is_symlink(dir / "a.png"));
    EXPECT_EQ(filesIn(dir.path()), 5u) << "no temporary left";
}

TEST(AtomicFile, AWriterThatThrowsLeavesNoTemporaryAndTheMessageNamesTheFile)
{
    // The temporary exists before the writer runs: a writer's exception removes it, and a writer's OutputError that
    // names the temporary names the user's file instead.
    const test::ScratchDir dir;
    try
    {
        writeAtomically(dir / "a.csv", [](const std::filesystem::path& tmp) -> bool {
            throw OutputError(fmt::format("cannot write '{}': the disk is full", tmp.string()));
        });
        ADD_FAILURE() << "no error";
    }
    catch (const OutputError& e)
    {
        EXPECT_EQ(std::string(e.what()), fmt::format("cannot write '{}': the disk is full", (dir / "a.csv").string()));
    }
    EXPECT_THROW(writeAtomically(dir / "b.csv", [](const std::filesystem::path&) -> bool { throw Error("other"); }),
                 Error);
    EXPECT_EQ(filesIn(dir.path()), 0u) << "no temporary left";
}

TEST(OutputSet, AFailingFileLeavesNoneOfTheSetBehind)
{
    const test::ScratchDir dir;
    for (int failing = 0; failing < 3; ++failing)
    {
        OutputSet set;
        for (int i = 0; i < 3; ++i)
            set.add(dir / fmt::format("f{}.txt", i), [=](const std::filesystem::path& tmp) {
                if (i == failing)
                    throw OutputError("cannot write it");
                writeFileAtomically(tmp, "x");
            });
        EXPECT_THROW(set.commit(), OutputError);
        EXPECT_EQ(filesIn(dir.path()), 0u) << "file " << failing << " failing";
    }
    // A rename that fails (the stats path became a folder after it was added) removes the files already put in
    // place.
    OutputSet set;
    set.add(dir / "a.png", [](const std::filesystem::path& tmp) { writeFileAtomically(tmp, "png"); });
    set.add(dir / "d.json", [](const std::filesystem::path& tmp) { writeFileAtomically(tmp, "{}"); });
    std::filesystem::create_directory(dir / "d.json");
    EXPECT_THROW(set.commit(), OutputError);
    EXPECT_FALSE(std::filesystem::exists(dir / "a.png"));
    EXPECT_EQ(filesIn(dir.path()), 1u); // the folder alone
}

TEST(OutputSet, AWriteThatFailsNamesTheUsersFileAndTheReason)
{
    // The writer fails on the temporary it is given, with the C library's reason; the message names the file
    // the user asked for, not the temporary (a full disk read "cannot write 'out.pfm.pending'").
    const test::ScratchDir dir;
    OutputSet set;
    set.add(dir / "out.pfm", [](const std::filesystem::path& tmp) {
        writeAtomically(tmp, [](const std::filesystem::path&) {
            errno = ENOSPC;
            return false;
        });
    });
    try
    {
        set.commit();
        ADD_FAILURE() << "the failed write was not reported";
    }
    catch (const OutputError& e)
    {
        const std::string message = e.what();
        EXPECT_NE(message.find("'" + (dir / "out.pfm").string() + "'"), std::string::npos) << message;
        EXPECT_EQ(message.find(".pending"), std::string::npos) << message;
        EXPECT_NE(message.find(std::strerror(ENOSPC)), std::string::npos) << message;
    }
    EXPECT_EQ(filesIn(dir.path()), 0u);
}

TEST(OutputSet, WritesThroughASymbolicLink)
{
    // The rename lands on the link's target: the link stays a link and the target holds the new bytes.
    const test::ScratchDir dir;
    writeFileAtomically(dir / "target.json", "old");
    std::filesystem::create_symlink("target.json", dir / "link.json");
    OutputSet set;
    set.add(dir / "link.json", [](const std::filesystem::path& tmp) { writeFileAtomically(tmp, "new"); });
    set.commit();
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.json"));
    EXPECT_EQ(std::filesystem::file_size(dir / "target.json"), 3u);
    writeFileAtomically(dir / "link.json", "newest");
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.json"));
    EXPECT_EQ(std::filesystem::file_size(dir / "target.json"), 6u);
    EXPECT_EQ(filesIn(dir.path()), 2u); // no temporary left
}

TEST(OutputSet, CheckWritableRefusesAFolderAMissingFolderAndAnUnwritableOne)
{
    const test::ScratchDir dir;
    EXPECT_NO_THROW(checkWritable(dir / "a.png", "--output"));
    EXPECT_EQ(filesIn(dir.path()), 0u); // the probe is gone
    std::filesystem::create_directory(dir / "d.json");
    EXPECT_THROW(checkWritable(dir / "d.json", "--stats"), OutputError);
    EXPECT_THROW(checkWritable(dir / "no" / "a.png", "--output"), OutputError);
    if (std::filesystem::is_directory("/proc/self"))
    {
        EXPECT_THROW(checkWritable("/proc/x.pfm", "--hdr"), OutputError); // root may write anywhere but here
    }
}
} // namespace
} // namespace rt
