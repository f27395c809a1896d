// The message of the AssetError a reader must throw, for tests of bad input.
#pragma once

#include <exception>
#include <string>

#include <gtest/gtest.h>

#include "Error.h"

namespace rt::test
{
/// Runs `f`, which must throw AssetError; returns its message. Fails the test for no error or another kind.
template <typename F>
std::string assetErrorOf(F&& f)
{
    try
    {
        f();
    }
    catch (const AssetError& e)
    {
        return e.what();
    }
    catch (const std::exception& e)
    {
        ADD_FAILURE() << "not an AssetError: " << e.what();
        return {};
    }
    ADD_FAILURE() << "no AssetError";
    return {};
}
} // namespace rt::test
