// Element-by-element comparison of two sequences for tests (a resumed run's samples against a
// straight run's, say): equal sizes, then `expect_same` on each pair under its index.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>

namespace rbcsim::testing {

template <class Sequence, class Compare>
void expect_each_same(const Sequence& actual, const Sequence& expected, Compare expect_same) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE(i);
    expect_same(actual[i], expected[i]);
  }
}

}  // namespace rbcsim::testing
