// IO/AtomicFile (issue 41): a write that the disk does not take whole is an error with no file left, never a
// short file reported as written; only a regular file (or a link to one) is replaced, never what a link to a
// device, a pipe or nothing points to. The disk's refusal is made with RLIMIT_FSIZE (SIGXFSZ ignored: write()
// returns EFBIG: Support/FileSizeLimit.h), which, unlike a full tmpfs, needs no privilege.
#include <gtest/gtest.h>

#ifndef _WIN32 // RLIMIT_FSIZE and mkfifo: POSIX

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>

#include "Error.h"
#include "IO/AtomicFile.h"
#include "IO/OutputSet.h"
#include "Image/Image.h"
#include "Image/ImageIO.h"
#include "Support/FileSizeLimit.h"
#include "Support/ScratchDir.h"

namespace rt
{
namespace
{
/// An image whose PNG is far larger than 4 KB: noise does not compress.
Image noise(int size)
{
    Image image(size, size);
    std::uint32_t state = 12345;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
        {
            vec3 c;
            for (int k = 0; k < 3; ++k)
            {
                state = state * 1664525u + 1013904223u;
                c[k] = float(state >> 8) / float(1u << 24);
            }
            image.at(x, y) = c;
        }
    return image;
}

TEST(AtomicFile, APngTheDiskDoesNotTakeWholeIsAnErrorWithNoFileLeft)
{
    // stb's file writer ignored fwrite's and fclose's errors: on a full disk the PNG was cut at 4 KB, and the
    // app printed "wrote" with status 0.
    const test::ScratchDir dir;
    const Image image = noise(64);
    {
        const test::FileSizeLimit limit(4096);
        try
        {
            writePng(dir / "a.png", image);
            ADD_FAILURE() << "a PNG cut short was reported as written";
        }
        catch (const OutputError& e)
        {
            EXPECT_NE(std::string(e.what()).find(std::strerror(EFBIG)), std::string::npos) << e.what();
        }
        EXPECT_THROW(writePfm(dir / "a.pfm", image), OutputError);
        EXPECT_THROW(writeFileAtomically(dir / "a.json", std::string(8192, 'x')), OutputError);
    }
    EXPECT_TRUE(dir.entries().empty()); // nothing half-written, no temporary
    writePng(dir / "a.png", image); // the same write with room
    EXPECT_GT(std::filesystem::file_size(dir / "a.png"), 4096u);
}

TEST(AtomicFile, OnlyARegularFileIsReplaced)
{
    const test::ScratchDir dir;
    // A pipe, directly or through a link: renaming over it would replace it (with a link to /dev/full, the
    // device itself was replaced by a PNG).
    ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0) << std::strerror(errno);
    std::filesystem::create_symlink(dir / "pipe", dir / "pipe.png");
    for (const char* name : {"pipe", "pipe.png"})
    {
        EXPECT_THROW(writeFileAtomically(dir / name, "x"), OutputError) << name;
        EXPECT_THROW(checkWritable(dir / name, "--output"), OutputError) << name;
        EXPECT_THROW(OutputSet().add(dir / name, [](const std::filesystem::path&) {}), OutputError) << name;
    }
    EXPECT_TRUE(std::filesystem::is_fifo(dir / "pipe"));
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "pipe.png"));
    // A link to a device is refused before anything is written, naming what it points to.
    std::filesystem::create_symlink("/dev/null", dir / "null.png");
    try
    {
        checkWritable(dir / "null.png", "--output");
        ADD_FAILURE() << "a link to /dev/null was accepted";
    }
    catch (const OutputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("'/dev/null', a device"), std::string::npos) << e.what();
    }
    // A link that points nowhere: refused, the link kept.
    std::filesystem::create_symlink(dir / "nothing" / "x.png", dir / "dangling.png");
    EXPECT_THROW(writeFileAtomically(dir / "dangling.png", "x"), OutputError);
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "dangling.png"));
    EXPECT_EQ(dir.entries().size(), 4u); // the pipe and the three links: no temporary left
    // A link to a regular file is written through and stays a link.
    writeFileAtomically(dir / "file.txt", "old");
    std::filesystem::create_symlink("file.txt", dir / "file-link.txt");
    EXPECT_NO_THROW(checkWritable(dir / "file-link.txt", "--stats"));
    writeFileAtomically(dir / "file-link.txt", "newer");
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "file-link.txt"));
    EXPECT_EQ(std::filesystem::file_size(dir / "file.txt"), 5u);
}
} // namespace
} // namespace rt

#endif
