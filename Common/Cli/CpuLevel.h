// Whether the CPU running this code has the instructions of an x86-64 micro-architecture level (the psABI's
// x86-64-v3: AVX2, FMA, BMI1/2, F16C, LZCNT, MOVBE; x86-64-v4: v3 and AVX-512 F/BW/CD/DQ/VL). Used by the
// build to pick the level it compiles for (CMakeLists.txt, RT_X86_LEVEL=auto) and by the apps to refuse to
// start on a CPU without the level they were built for (CpuCheck.cpp). Header-only and free of the standard
// library: the build's probe compiles it on its own, and the apps' check runs before static initialisers.
#pragma once

namespace rt
{
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
inline bool cpuHasX86Level3()
{
    __builtin_cpu_init();
#if !defined(__clang__) && __GNUC__ >= 12
    return __builtin_cpu_supports("x86-64-v3");
#else
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi") &&
           __builtin_cpu_supports("bmi2");
#endif
}

inline bool cpuHasX86Level4()
{
    __builtin_cpu_init();
#if !defined(__clang__) && __GNUC__ >= 12
    return __builtin_cpu_supports("x86-64-v4");
#else
    return cpuHasX86Level3() && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
           __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("avx512dq") &&
           __builtin_cpu_supports("avx512vl");
#endif
}
#endif
} // namespace rt
