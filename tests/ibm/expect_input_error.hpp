// Test helper: an action must throw rbcsim::InputError whose one-line message contains each of
// the given fragments (the config key, the bad value, the valid choices).
#pragma once

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <string_view>

#include "common/errors.hpp"

template <typename Action>
void expect_input_error_mentioning(Action action,
                                   std::initializer_list<std::string_view> fragments) {
  try {
    action();
    ADD_FAILURE() << "no InputError";
  } catch (const rbcsim::InputError& error) {
    const std::string message = error.what();
    for (const auto fragment : fragments) {
      EXPECT_NE(message.find(fragment), std::string::npos) << message;
    }
  }
}
