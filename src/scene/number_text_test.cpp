#include "scene/number_text.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

namespace prt {
namespace {

TEST(SceneNumberText, ParsesDecimalForms) {
  EXPECT_EQ(parseDouble("1.5").value, 1.5);
  EXPECT_EQ(parseDouble("-2").value, -2.0);
  EXPECT_EQ(parseDouble("+0.25").value, 0.25);
  EXPECT_EQ(parseDouble(".5").value, 0.5);
  EXPECT_EQ(parseDouble("3.").value, 3.0);
  EXPECT_EQ(parseDouble("1e-3").value, 1e-3);
  EXPECT_EQ(parseDouble("2E+2").value, 200.0);
  EXPECT_EQ(parseDouble("4.9e-324").status, NumberStatus::Ok);  // subnormals are fine
}

TEST(SceneNumberText, ClassifiesBadNumbers) {
  for (const char* text : {"1.2.3", "1e", "0x10", "--1", "+-1", "++1", "-", "1,5", "1f", ""}) {
    EXPECT_EQ(parseDouble(text).status, NumberStatus::Malformed) << text;
  }
  EXPECT_EQ(parseDouble("1e400").status, NumberStatus::OutOfRange);
  EXPECT_EQ(parseDouble("-1e400").status, NumberStatus::OutOfRange);
  EXPECT_EQ(parseDouble("1e-400").status, NumberStatus::OutOfRange);
  EXPECT_EQ(parseDouble("-inf").status, NumberStatus::NotFinite);
  EXPECT_EQ(parseDouble("-nan").status, NumberStatus::NotFinite);
}

TEST(SceneNumberText, IntegersAreDigitsOnly) {
  EXPECT_EQ(parseInteger("320").value, 320);
  EXPECT_EQ(parseInteger("+7").value, 7);
  EXPECT_EQ(parseInteger("-3").value, -3);
  EXPECT_EQ(parseInteger("3.0").status, NumberStatus::Malformed);
  EXPECT_EQ(parseInteger("3e2").status, NumberStatus::Malformed);
  EXPECT_EQ(parseInteger("99999999999999999999").status, NumberStatus::OutOfRange);
}

TEST(SceneNumberText, FormatIsShortestAndRoundTripsExactly) {
  EXPECT_EQ(formatDouble(0.1), "0.1");
  EXPECT_EQ(formatDouble(320), "320");
  EXPECT_EQ(formatDouble(1e-300), "1e-300");
  EXPECT_EQ(formatDouble(-0.0), "-0");
  const double values[] = {1.0 / 3.0,
                           0.1 + 0.2,
                           1e-300,
                           5e-324,
                           1.7976931348623157e308,
                           -2.5,
                           std::nextafter(1.0, 2.0),
                           123456789.123456789};
  for (const double value : values) {
    const ParsedNumber<double> back = parseDouble(formatDouble(value));
    ASSERT_EQ(back.status, NumberStatus::Ok) << formatDouble(value);
    EXPECT_EQ(std::bit_cast<uint64_t>(back.value), std::bit_cast<uint64_t>(value));
  }
}

}  // namespace
}  // namespace prt
