#pragma once
// The message of the std::invalid_argument a parse throws: how the option tests compare
// whole error messages.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace tools::test {

// Fails the test when `parse` throws nothing.
template <typename Parse>
std::string errorOf(Parse parse) {
    try {
        parse();
    } catch (const std::invalid_argument& error) {
        return error.what();
    }
    ADD_FAILURE() << "no std::invalid_argument thrown";
    return {};
}

} // namespace tools::test
