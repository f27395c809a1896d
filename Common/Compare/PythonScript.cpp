#include "Compare/PythonScript.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>

#ifdef _WIN32
#include <cstdlib>
#else
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
extern char** environ;
#endif

#include <spdlog/fmt/fmt.h>

#include "Assets/AssetPaths.h"
#include "IO/AtomicFile.h"
#include "Error.h"

namespace rt::compare
{
namespace
{
/// Exit status of `python args...`, or -1 when it could not start. `quiet` sends its output to /dev/null.
int spawnPython(const std::string& python, const std::vector<std::string>& args, bool quiet)
{
#ifdef _WIN32
    std::string command = python;
    for (const std::string& a : args)
        command += " \"" + a + "\"";
    if (quiet)
        command += " >NUL 2>&1";
    return std::system(command.c_str());
#else
    std::vector<std::string> argv{python};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<char*> cargv;
    for (std::string& a : argv)
        cargv.push_back(a.data());
    cargv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (quiet)
    {
        posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
        posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    }
    pid_t pid = 0;
    const int spawned = posix_spawnp(&pid, python.c_str(), &actions, nullptr, cargv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0)
        return -1;
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
#endif
}
/// The first of $RT_PYTHON, `python3` on the PATH and Debian's /usr/bin/python3 that imports matplotlib and
/// numpy (a PATH may lead to a python of its own, such as pyenv's, without Debian's packages); empty if none.
const std::string& plottingPython()
{
    static const std::string chosen = [] {
        std::vector<std::string> candidates;
        if (const char* env = std::getenv("RT_PYTHON"); env && *env)
            candidates.emplace_back(env);
        candidates.emplace_back("python3");
        candidates.emplace_back("/usr/bin/python3");
        for (const std::string& python : candidates)
            if (spawnPython(python, {"-c", "import matplotlib, numpy"}, true) == 0)
                return python;
        return std::string();
    }();
    return chosen;
}
} // namespace

std::filesystem::path scriptPath(const std::string& name)
{
    const std::filesystem::path path = executableDir() / "scripts" / name;
    if (!std::filesystem::is_regular_file(path))
        throw AssetError(fmt::format("the app's script {} is missing (it is copied there by the build)",
                                     path.string()));
    return path;
}

void requireMatplotlib(const std::string& flag)
{
    if (plottingPython().empty())
        throw UsageError(fmt::format("{} draws with python3 and matplotlib, which this machine lacks (Debian: "
                                     "apt-get install python3-matplotlib)",
                                     flag));
}

void runPythonScript(const std::filesystem::path& script, const std::vector<std::string>& args)
{
    std::vector<std::string> all{script.string()};
    all.insert(all.end(), args.begin(), args.end());
    const int status = plottingPython().empty() ? -1 : spawnPython(plottingPython(), all, false);
    if (status != 0)
        throw OutputError(fmt::format("{} failed ({})", script.filename().string(),
                                      status < 0 ? "python3 did not start" : fmt::format("status {}", status)));
}

void drawFigure(const std::filesystem::path& figure, const std::filesystem::path& script,
                const std::vector<std::string>& inputs)
{
    std::string failure;
    try
    {
        writeAtomically(figure, [&](const std::filesystem::path& tmp) {
            try
            {
                std::vector<std::string> args = inputs;
                args.push_back(tmp.string());
                runPythonScript(script, args);
                return true;
            }
            catch (const Error& e)
            {
                failure = e.what(); // returning false removes the partial file
                return false;
            }
        });
    }
    catch (const OutputError&)
    {
        if (failure.empty())
            throw;
        throw OutputError(fmt::format("cannot write '{}': {}", figure.string(), failure));
    }
}
} // namespace rt::compare
