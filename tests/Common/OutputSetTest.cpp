// IO/OutputSet: a render's outputs are written all or none, and a path that cannot be written is found
// before the render (issue 13: a stats path that was a folder failed after the PNG was written).
#include <gtest/gtest.h>
#include <spdlog/fmt/fmt.h>

#include <filesystem>
#include <string>

#include "Error.h"
#include "IO/AtomicFile.h"
#include "IO/OutputSet.h"
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
    // A rename that fails (the stats path is a folder) removes the files already put in place.
    std::filesystem::create_directory(dir / "d.json");
    OutputSet set;
    set.add(dir / "a.png", [](const std::filesystem::path& tmp) { writeFileAtomically(tmp, "png"); });
    set.add(dir / "d.json", [](const std::filesystem::path& tmp) { writeFileAtomically(tmp, "{}"); });
    EXPECT_THROW(set.commit(), OutputError);
    EXPECT_FALSE(std::filesystem::exists(dir / "a.png"));
    EXPECT_EQ(filesIn(dir.path()), 1u); // the folder alone
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
