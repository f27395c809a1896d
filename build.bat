@echo off
rem Set up, build, and run the main job or the tests on Windows with vcpkg (the Debian route is build.sh).
rem   build.bat          install the vcpkg packages, configure and build (Release) into build\
rem   build.bat run      ... then render cornell-box-lights to out\
rem   build.bat test     ... then run the test suite (everything but the label "heavy")
rem Needs: Visual Studio 2022 (C++20), CMake, the Vulkan SDK (glslc, loader, validation layers),
rem and vcpkg on PATH or in VCPKG_ROOT.
setlocal
cd /d "%~dp0"
set MODE=%1
if "%MODE%"=="" set MODE=build

if "%VCPKG_ROOT%"=="" (
    for %%v in (vcpkg.exe) do set VCPKG_ROOT=%%~dp$PATH:v
)
if "%VCPKG_ROOT%"=="" (
    echo build.bat: vcpkg not found: put it on PATH or set VCPKG_ROOT 1>&2
    exit /b 1
)

"%VCPKG_ROOT%\vcpkg.exe" install --triplet x64-windows glm spdlog stb tinyobjloader tinygltf tbb cli11 nlohmann-json zlib ^
    gtest benchmark vulkan || exit /b 1

rem The windows compile Dear ImGui's backends from Debian's libimgui-dev sources (CMakeLists.txt), which vcpkg
rem does not install: this route builds the headless apps, the engines and the tests.
cmake -S . -B build -G "Visual Studio 17 2022" -A x64 -DRT_BUILD_GUI=OFF ^
    -DCMAKE_TOOLCHAIN_FILE="%VCPKG_ROOT%\scripts\buildsystems\vcpkg.cmake" || exit /b 1
cmake --build build --config Release --parallel || exit /b 1

if "%MODE%"=="run" (
    if not exist out mkdir out
    build\bin\Release\ray-tracing-cpu.exe --headless --scene cornell-box-lights --width 600 --spp 512 ^
        --output out\cornell-box-lights.png --hdr out\cornell-box-lights.pfm --stats out\cornell-box-lights.json || exit /b 1
)
if "%MODE%"=="test" (
    ctest --test-dir build -C Release --output-on-failure -LE heavy || exit /b 1
)
endlocal
