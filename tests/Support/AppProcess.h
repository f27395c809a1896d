// Running an app of this project as a user runs it, from a test: its exit status and everything it printed.
// POSIX only (popen, the exit status macros); the callers are compiled out on Windows.
#pragma once

#include <string>

namespace rt::test
{
struct AppRun
{
    int status; // exit status; -1 when the app could not be started or did not exit normally
    std::string output; // stdout and stderr
};

/// Runs `'app' arguments 2>&1` through the shell, with `environment` ("NAME=value ...") before it.
AppRun runApp(const std::string& app, const std::string& arguments, const std::string& environment = "");
} // namespace rt::test
