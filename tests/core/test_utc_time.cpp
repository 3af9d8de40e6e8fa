// ISO 8601 times (core/utc_time.hpp): the forms the library reads, the
// calendar checked, zones applied, and what it writes reads back.
#include <gtest/gtest.h>

#include "deepguide/core/error.hpp"
#include "deepguide/core/utc_time.hpp"

using namespace deepguide;

namespace {
// 2019-03-07T15:00:00Z: 17962 days after 1970-01-01, plus 15 h.
constexpr double kMarch7 = 17962.0 * 86400.0 + 15.0 * 3600.0;
}  // namespace

TEST(UtcTime, ReadsTheCommonForms) {
  EXPECT_EQ(parse_iso8601("2019-03-07T15:00:00Z", true), kMarch7);
  EXPECT_EQ(parse_iso8601("2019-03-07t15:00:00z", true), kMarch7);
  EXPECT_EQ(parse_iso8601("  2019-03-07 15:00Z ", true), kMarch7);
  EXPECT_EQ(parse_iso8601("2019-03-07T17:00:00+02:00", true), kMarch7);
  EXPECT_EQ(parse_iso8601("2019-03-07T17:30+0230", true), kMarch7);
  EXPECT_EQ(parse_iso8601("2019-03-07T09:30:00-05:30", true), kMarch7);
  EXPECT_EQ(parse_iso8601("2019-03-07 15:00:00 UTC", true), kMarch7);
  EXPECT_EQ(parse_iso8601("2019-03-07T15:00:00.250Z", true), kMarch7 + 0.25);
  EXPECT_EQ(parse_iso8601("2019-03-07T15:00:00,5Z", true), kMarch7 + 0.5);
  EXPECT_EQ(parse_iso8601("2019-03-07T14:59:60Z", true), kMarch7);  // a leap second
  // CF's reference dates: no zone (UTC), no leading zeros, a date alone.
  EXPECT_EQ(parse_iso8601("2019-3-7 15:0:0", false), kMarch7);
  EXPECT_EQ(parse_iso8601("1970-01-01", false), 0.0);
  EXPECT_EQ(parse_iso8601("1-1-1", false), -62135596800.0);
}

TEST(UtcTime, RefusesWhatIsNotATime) {
  for (const char* bad :
       {"", "  ", "2019-03-07T15:00:00Zjunk", "2019-02-30T00:00:00Z", "2019-13-01T00:00:00Z", "2019-03-07T24:00:00Z",
        "2019-03-07T24:00:01Z", "2019-03-07T15:60:00Z", "2019-03-07T15:00:00.Z", "2019-03-07T15Z",
        "2019-03-07T15:00:00+24:00", "20190307T150000Z", "2019-03-07T15:00:00 Mars", "yesterday"}) {
    EXPECT_FALSE(parse_iso8601(bad, false)) << bad;
  }
  // A clock without a zone is a place nobody named, where a zone is required.
  EXPECT_FALSE(parse_iso8601("2019-03-07T15:00:00", true));
  EXPECT_EQ(parse_iso8601("2019-03-07T15:00:00", false), kMarch7);
  EXPECT_THROW(parse_utc("noon", "--depart"), InputError);
  try {
    parse_utc("noon", "--depart");
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "--depart: expected a UTC time such as 2019-03-07T15:00:00Z, got 'noon'");
  }
}

TEST(UtcTime, WritesWhatItReads) {
  EXPECT_EQ(format_utc(kMarch7), "2019-03-07T15:00:00Z");
  EXPECT_EQ(format_utc(kMarch7 + 0.4), "2019-03-07T15:00:00Z");
  EXPECT_EQ(format_utc(kMarch7 + 0.25, true), "2019-03-07T15:00:00.250Z");
  EXPECT_EQ(format_utc(kMarch7, true), "2019-03-07T15:00:00Z");
  EXPECT_EQ(format_utc(-0.5, true), "1969-12-31T23:59:59.500Z");
  EXPECT_EQ(format_utc(std::numeric_limits<double>::quiet_NaN()), "?");
  for (double t : {0.0, kMarch7, 1.8e9 + 0.123, -1e9}) {
    EXPECT_NEAR(*parse_iso8601(format_utc(t, true), true), t, 5e-4) << t;
  }
}
