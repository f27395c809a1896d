// A disk that fills up mid-write, made without privilege: RLIMIT_FSIZE with SIGXFSZ ignored, so that a write past
// the limit fails with EFBIG instead of killing the process. POSIX only.
#pragma once

#include <sys/resource.h>

#include <csignal>

namespace rt::test
{
/// Limits the size of files this process writes to `bytes` while it lives; restores the limit and SIGXFSZ's
/// handler when destroyed.
class FileSizeLimit
{
public:
    explicit FileSizeLimit(rlim_t bytes)
    {
        getrlimit(RLIMIT_FSIZE, &m_saved);
        m_savedHandler = std::signal(SIGXFSZ, SIG_IGN);
        rlimit limit = m_saved;
        limit.rlim_cur = bytes;
        setrlimit(RLIMIT_FSIZE, &limit);
    }
    ~FileSizeLimit()
    {
        setrlimit(RLIMIT_FSIZE, &m_saved);
        std::signal(SIGXFSZ, m_savedHandler);
    }
    FileSizeLimit(const FileSizeLimit&) = delete;
    FileSizeLimit& operator=(const FileSizeLimit&) = delete;

private:
    rlimit m_saved{};
    void (*m_savedHandler)(int) = nullptr;
};
} // namespace rt::test
