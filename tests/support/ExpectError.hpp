#pragma once
// The shape every user-facing error must have: og::InputError, one line, "LABEL: problem".
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "core/Error.hpp"

namespace og::test {

/// Expects `f` to throw og::InputError whose message starts with "label: ", contains
/// `fragment` and is a single line.
inline void expectInputError(const std::string& label, const std::string& fragment,
                             const std::function<void()>& f) {
  try {
    f();
    ADD_FAILURE() << "expected og::InputError from " << label;
  } catch (const og::InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(label + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

}  // namespace og::test
