#include "Support/AppProcess.h"

#include <cstdio>

#ifndef _WIN32
#include <sys/wait.h>
#endif

namespace rt::test
{
AppRun runApp([[maybe_unused]] const std::string& app, [[maybe_unused]] const std::string& arguments,
              [[maybe_unused]] const std::string& environment)
{
    AppRun run{-1, {}};
#ifndef _WIN32
    const std::string command = environment + " '" + app + "' " + arguments + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe)
        return run;
    char buffer[4096];
    while (std::size_t n = std::fread(buffer, 1, sizeof(buffer), pipe))
        run.output.append(buffer, n);
    const int status = pclose(pipe);
    run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
#endif
    return run;
}
} // namespace rt::test
