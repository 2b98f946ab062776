#include "config/range.hpp"

#include <gtest/gtest.h>

#include "common/errors.hpp"

namespace {

using rbcsim::config::parse_range;
using Values = std::vector<double>;

std::string range_error(const std::string& text) {
  try {
    parse_range(text, "--rates", 5);
  } catch (const rbcsim::InputError& error) {
    return error.what();
  }
  return "";
}

TEST(Range, SingleNumbersAndLists) {
  EXPECT_EQ(parse_range("500", "--rates", 5), Values({500.0}));
  EXPECT_EQ(parse_range("1e3", "--rates", 5), Values({1000.0}));
  EXPECT_EQ(parse_range("0, 50,200", "--forces", 5), Values({0.0, 50.0, 200.0}));
}

TEST(Range, StepIncludesStopWhenItLandsOnAStep) {
  EXPECT_EQ(parse_range("0:2000:500", "--rates", 5), Values({0, 500, 1000, 1500, 2000}));
  EXPECT_EQ(parse_range("0:10:3", "--rates", 5), Values({0, 3, 6, 9}));
  EXPECT_EQ(parse_range("200:0:-100", "--rates", 5), Values({200, 100, 0}));
  // 0.3/0.1 is 2.9999999999999996 in binary floating point; the stop still lands.
  const auto tenths = parse_range("0:0.3:0.1", "--rates", 5);
  ASSERT_EQ(tenths.size(), 4u);
  EXPECT_EQ(tenths.back(), 0.3);
  EXPECT_EQ(parse_range("7:7:1", "--rates", 5), Values({7}));
}

TEST(Range, CountGivesEvenlySpacedValues) {
  EXPECT_EQ(parse_range("0:200/5", "--forces", 5), Values({0, 50, 100, 150, 200}));
  EXPECT_EQ(parse_range("1:0/3", "--forces", 5), Values({1, 0.5, 0}));
  EXPECT_EQ(parse_range("0:2000", "--rates", 3), Values({0, 1000, 2000}));  // caller's count
  EXPECT_EQ(parse_range("5:5/4", "--rates", 5), Values({5}));
}

TEST(Range, Diagnostics) {
  EXPECT_EQ(range_error("0:10:0"), "--rates: range \"0:10:0\": step must not be 0");
  EXPECT_EQ(range_error("0:10:-1"), "--rates: range \"0:10:-1\": step -1 goes away from the stop");
  EXPECT_EQ(range_error("0:ten"), "--rates: range \"0:ten\": \"ten\" is not a number");
  EXPECT_EQ(range_error(""), "--rates: range \"\": \"\" is not a number");
  EXPECT_EQ(range_error("1,,2"), "--rates: range \"\": \"\" is not a number");
  EXPECT_EQ(range_error("0:1/1"),
            "--rates: range \"0:1/1\": count must be a whole number from 2 to 100000");
  EXPECT_EQ(range_error("0:1/2.5"),
            "--rates: range \"0:1/2.5\": count must be a whole number from 2 to 100000");
  EXPECT_EQ(range_error("0:1:0.5/2"),
            "--rates: range \"0:1:0.5/2\": use either :step or /count, not both");
  EXPECT_EQ(range_error("0:1e9:1"), "--rates: range \"0:1e9:1\": more than 100000 values");
  EXPECT_EQ(range_error("0:1:2:3"), "--rates: range \"0:1:2:3\": \"2:3\" is not a number");
  EXPECT_EQ(range_error("inf"), "--rates: range \"inf\": \"inf\" is not a number");
}

}  // namespace
