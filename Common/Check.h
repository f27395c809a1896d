// RT_CHECK / RT_DCHECK: assertions for the program's own invariants (a pdf that must be positive, an index
// inside its array, a BVH node with children), in the spirit of pbrt-v4's util/check.h. A failed check is
// a bug in this program, never the user's doing: it prints one line to stderr (file:line, the expression
// and, for the comparison forms, both values) and aborts, leaving a core dump or a debugger stop at the
// spot. Anything the user can cause (a bad flag, an unknown scene, a missing file, no Vulkan device)
// throws an rt::Error subclass from Error.h instead, which the apps report with their exit codes.
//
//   RT_CHECK(cond)                      always on
//   RT_CHECK_EQ(a, b)  _NE _LT _LE _GT _GE   always on; evaluate a and b once each, print both on failure
//   RT_DCHECK(cond), RT_DCHECK_EQ(a, b), ... on without NDEBUG (Debug builds); in Release they evaluate
//                                       nothing but still compile their arguments, so they cannot rot
//
// The comparison forms format their values with fmt: for Common's types (vectors, Aabb, the settings'
// enums) include Format.h where the check is written. Two integers compare by value whatever their
// signedness (std::cmp_less and friends), so RT_CHECK_LT(i, v.size()) with a negative int i fails.
// Pointers print as addresses.
#pragma once

#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include <spdlog/fmt/fmt.h>

namespace rt::detail
{
/// The failure path of every check: logs "file:line: check failed: message" to stderr, then std::abort().
/// Out of line (Check.cpp) so that a check's fast path is one compare and one predicted branch.
[[noreturn, gnu::cold]] void checkFailed(const char* file, int line, std::string_view message);

/// Integers that std::cmp_equal and friends accept (not bool, not the character types).
template <typename T>
inline constexpr bool kCheckInteger =
    std::is_integral_v<T> && !std::is_same_v<T, bool> && !std::is_same_v<T, char> &&
    !std::is_same_v<T, wchar_t> && !std::is_same_v<T, char8_t> && !std::is_same_v<T, char16_t> &&
    !std::is_same_v<T, char32_t>;

template <typename A, typename B>
inline constexpr bool kCheckIntegers = kCheckInteger<A> && kCheckInteger<B>;

template <typename A, typename B>
constexpr bool checkEq(const A& a, const B& b)
{
    if constexpr (kCheckIntegers<A, B>)
        return std::cmp_equal(a, b);
    else
        return a == b;
}

template <typename A, typename B>
constexpr bool checkNe(const A& a, const B& b)
{
    if constexpr (kCheckIntegers<A, B>)
        return std::cmp_not_equal(a, b);
    else
        return a != b;
}

template <typename A, typename B>
constexpr bool checkLt(const A& a, const B& b)
{
    if constexpr (kCheckIntegers<A, B>)
        return std::cmp_less(a, b);
    else
        return a < b;
}

template <typename A, typename B>
constexpr bool checkLe(const A& a, const B& b)
{
    if constexpr (kCheckIntegers<A, B>)
        return std::cmp_less_equal(a, b);
    else
        return a <= b;
}

template <typename A, typename B>
constexpr bool checkGt(const A& a, const B& b)
{
    if constexpr (kCheckIntegers<A, B>)
        return std::cmp_greater(a, b);
    else
        return a > b;
}

template <typename A, typename B>
constexpr bool checkGe(const A& a, const B& b)
{
    if constexpr (kCheckIntegers<A, B>)
        return std::cmp_greater_equal(a, b);
    else
        return a >= b;
}

template <typename T>
std::string checkValueText(const T& value)
{
    // fmt refuses non-void pointers; a char* compared here is a pointer too, so it prints as one.
    if constexpr (std::is_pointer_v<T>)
        return fmt::format("{}", fmt::ptr(value));
    else
        return fmt::format("{}", value);
}

/// Formats "expr with a = <a>, b = <b>" and fails; a template, but cold and never inlined.
template <typename A, typename B>
[[noreturn, gnu::cold, gnu::noinline]] void checkCompareFailed(const char* file, int line, const char* expr,
                                                               const char* aText, const char* bText,
                                                               const A& a, const B& b)
{
    checkFailed(
        file, line,
        fmt::format("{} with {} = {}, {} = {}", expr, aText, checkValueText(a), bText, checkValueText(b)));
}
} // namespace rt::detail

#define RT_CHECK(cond)                                                                                       \
    do                                                                                                       \
    {                                                                                                        \
        if (!(cond)) [[unlikely]]                                                                            \
            ::rt::detail::checkFailed(__FILE__, __LINE__, #cond);                                            \
    } while (false)

#define RT_CHECK_OP_(a, b, op, compare)                                                                      \
    do                                                                                                       \
    {                                                                                                        \
        const auto& rtCheckA_ = (a);                                                                         \
        const auto& rtCheckB_ = (b);                                                                         \
        if (!::rt::detail::compare(rtCheckA_, rtCheckB_)) [[unlikely]]                                       \
            ::rt::detail::checkCompareFailed(__FILE__, __LINE__, #a " " #op " " #b, #a, #b, rtCheckA_,       \
                                             rtCheckB_);                                                     \
    } while (false)

#define RT_CHECK_EQ(a, b) RT_CHECK_OP_(a, b, ==, checkEq)
#define RT_CHECK_NE(a, b) RT_CHECK_OP_(a, b, !=, checkNe)
#define RT_CHECK_LT(a, b) RT_CHECK_OP_(a, b, <, checkLt)
#define RT_CHECK_LE(a, b) RT_CHECK_OP_(a, b, <=, checkLe)
#define RT_CHECK_GT(a, b) RT_CHECK_OP_(a, b, >, checkGt)
#define RT_CHECK_GE(a, b) RT_CHECK_OP_(a, b, >=, checkGe)

#ifdef NDEBUG
#define RT_DCHECK_IS_ON 0
// Compiled (names resolve, types check, no unused-variable warnings) but discarded: nothing is evaluated.
#define RT_DCHECK_DISCARD_(check)                                                                            \
    do                                                                                                       \
    {                                                                                                        \
        if constexpr (false)                                                                                 \
            check;                                                                                           \
    } while (false)
#define RT_DCHECK(cond) RT_DCHECK_DISCARD_(RT_CHECK(cond))
#define RT_DCHECK_EQ(a, b) RT_DCHECK_DISCARD_(RT_CHECK_EQ(a, b))
#define RT_DCHECK_NE(a, b) RT_DCHECK_DISCARD_(RT_CHECK_NE(a, b))
#define RT_DCHECK_LT(a, b) RT_DCHECK_DISCARD_(RT_CHECK_LT(a, b))
#define RT_DCHECK_LE(a, b) RT_DCHECK_DISCARD_(RT_CHECK_LE(a, b))
#define RT_DCHECK_GT(a, b) RT_DCHECK_DISCARD_(RT_CHECK_GT(a, b))
#define RT_DCHECK_GE(a, b) RT_DCHECK_DISCARD_(RT_CHECK_GE(a, b))
#else
#define RT_DCHECK_IS_ON 1
#define RT_DCHECK(cond) RT_CHECK(cond)
#define RT_DCHECK_EQ(a, b) RT_CHECK_EQ(a, b)
#define RT_DCHECK_NE(a, b) RT_CHECK_NE(a, b)
#define RT_DCHECK_LT(a, b) RT_CHECK_LT(a, b)
#define RT_DCHECK_LE(a, b) RT_CHECK_LE(a, b)
#define RT_DCHECK_GT(a, b) RT_CHECK_GT(a, b)
#define RT_DCHECK_GE(a, b) RT_CHECK_GE(a, b)
#endif
