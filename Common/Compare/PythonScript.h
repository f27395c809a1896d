// The figures of --compare (plots, the equal-time grid) are drawn by matplotlib scripts that ship beside the
// app in <bin>/scripts (copied there from Common/Compare at build time); these run them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rt::compare
{
/// <folder of the executable>/scripts/`name`. Throws AssetError when it is not there.
std::filesystem::path scriptPath(const std::string& name);

/// Checks, before any rendering, that a python (plottingPython in the .cpp: $RT_PYTHON, python3, then
/// /usr/bin/python3) imports matplotlib and numpy. Throws UsageError
/// naming `flag` and the Debian package when it does not.
void requireMatplotlib(const std::string& flag);

/// Runs `python script args...` with that python (no shell), its output on this process's stdout and stderr. Throws
/// OutputError naming the script when it cannot start or exits with a non-zero status.
void runPythonScript(const std::filesystem::path& script, const std::vector<std::string>& args);

/// Runs `python3 script inputs... <temporary sibling of figure>` and renames its output over `figure`, so a
/// failed script leaves no file. Throws OutputError naming the figure and why.
void drawFigure(const std::filesystem::path& figure, const std::filesystem::path& script,
                const std::vector<std::string>& inputs);
} // namespace rt::compare
