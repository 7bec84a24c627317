#include <gtest/gtest.h>

#include "core/Time.hpp"

using og::UtcTime;

TEST(UtcTime, ParsesIso8601Forms) {
  const auto t = UtcTime::parseIso8601("2000-01-01T12:00:00Z");
  ASSERT_TRUE(t);
  EXPECT_DOUBLE_EQ(t->julianDate(), 2451545.0);  // J2000.0
  EXPECT_DOUBLE_EQ(UtcTime::parseIso8601("1970-01-01")->unixSeconds, 0.0);
  EXPECT_DOUBLE_EQ(UtcTime::parseIso8601("2024-06-20 20:51")->unixSeconds,
                   UtcTime::fromCivil(2024, 6, 20, 20, 51).unixSeconds);
  EXPECT_NEAR(UtcTime::parseIso8601("2024-06-20T20:51:30.25Z")->unixSeconds -
                  UtcTime::fromCivil(2024, 6, 20, 20, 51).unixSeconds,
              30.25, 1e-6);
  // A zone offset is applied: 14:00+02:00 is 12:00Z.
  EXPECT_DOUBLE_EQ(UtcTime::parseIso8601("2024-01-01T14:00:00+02:00")->unixSeconds,
                   UtcTime::parseIso8601("2024-01-01T12:00:00Z")->unixSeconds);
  EXPECT_EQ(UtcTime::parseIso8601("2024-02-29T23:59:59Z")->toIso8601(), "2024-02-29T23:59:59Z");
}

TEST(UtcTime, RejectsMalformed) {
  for (const char* bad : {"", "2024", "2024-13-01", "2023-02-29", "2024-01-32", "2024-01-01T25:00",
                          "2024-01-01T12:60", "2024-01-01T12:00:00Q", "24-01-01", "2024-01-01T12",
                          "2024-01-01T12:00:00.", "2024-01-01T12:00:00Zjunk", "not a time"}) {
    EXPECT_FALSE(UtcTime::parseIso8601(bad)) << bad;
  }
}
