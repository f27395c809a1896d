// Linked into each app (not into rt_common: a static library's object that nothing references would be
// dropped). A build for x86-64-v3 run on a CPU without AVX2 dies with SIGILL in whatever code runs first
// (static initialisers, CLI11 building the flags) before main could say why: this check runs before all of
// them (a constructor of priority 101), in code compiled for the baseline x86-64 (Common/CMakeLists.txt).
#if defined(RT_REQUIRES_AVX2) && defined(__GNUC__)
#include <cstdio>
#include <cstdlib>

namespace
{
__attribute__((constructor(101))) void requireAvx2()
{
    __builtin_cpu_init();
    if (!__builtin_cpu_supports("avx2"))
    {
        std::fputs("error: this build needs a CPU with AVX2 (x86-64-v3); rebuild with -DRT_X86_LEVEL=x86-64-v2\n",
                   stderr);
        std::_Exit(1);
    }
}
} // namespace
#endif
