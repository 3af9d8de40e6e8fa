// The frame rule (world/frame_scale.hpp): scale factors from PROJ against
// their closed forms, the frames it refuses and the ones it chooses.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "deepguide/core/error.hpp"
#include "deepguide/world/extent.hpp"
#include "deepguide/world/frame_scale.hpp"
#include "deepguide/world/local_frame.hpp"

using namespace deepguide;

namespace {

double rad(double deg) { return deg * std::numbers::pi / 180.0; }

// The refusal's one line, or "" when the frame keeps the rule.
std::string refusal(const std::string& crs, const LonLatExtent& area) {
  try {
    require_true_scale(LocalFrame::from_user_crs(crs), area, "the test area");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

LonLatExtent around(double lon, double lat, double half_deg = 0.02) {
  return {lon - half_deg, lon + half_deg, lat - half_deg, lat + half_deg};
}

}  // namespace

TEST(FrameScale, UtmScaleIsItsTransverseMercatorClosedForm) {
  const LocalFrame utm = LocalFrame::from_user_crs("EPSG:32632");  // central meridian 9 E
  const LocalFrame::Scale on = utm.scale_at({9.0, 54.0});
  EXPECT_NEAR(on.least, 0.9996, 1e-9);
  EXPECT_NEAR(on.greatest, 0.9996, 1e-9);
  // Off the meridian k = k0 / sqrt(1 - B^2), B = cos(lat) sin(dlon), on the
  // sphere; the ellipsoid changes k - k0 by about 1 % of itself.
  for (const double dlon : {1.0, 3.0, 5.0}) {
    for (const double lat : {0.0, 40.0, 70.0}) {
      const LocalFrame::Scale s = utm.scale_at({9.0 + dlon, lat});
      const double b = std::cos(rad(lat)) * std::sin(rad(dlon));
      const double k = 0.9996 / std::sqrt(1.0 - b * b);
      EXPECT_NEAR(s.greatest, k, 0.015 * (k - 0.9996) + 2e-6) << dlon << " " << lat;
      EXPECT_NEAR(s.least, s.greatest, 1e-7) << "conformal (PROJ differentiates numerically)";
    }
  }
}

TEST(FrameScale, MercatorsStretchBySecantOfLatitude) {
  for (const char* crs : {"EPSG:3857", "EPSG:3395"}) {
    const LocalFrame f = LocalFrame::from_user_crs(crs);
    for (const double lat : {0.0, 35.0, 60.0}) {
      const LocalFrame::Scale s = f.scale_at({9.0, lat});
      // Ellipsoidal Mercator: sec(lat) sqrt(1 - e^2 sin^2 lat); Web Mercator
      // is not conformal on the ellipsoid but close to that.
      const double e2 = 0.00669437999014;
      const double k = std::sqrt(1.0 - e2 * std::sin(rad(lat)) * std::sin(rad(lat))) / std::cos(rad(lat));
      EXPECT_NEAR(s.greatest, k, 0.008 * k) << crs << " " << lat;
    }
  }
}

TEST(FrameScale, PolarStereographicIsTrueAtItsStandardParallelOnly) {
  const LocalFrame north = LocalFrame::from_user_crs("EPSG:3413");  // true at 70 N
  EXPECT_NEAR(north.scale_at({-45.0, 70.0}).greatest, 1.0, 1e-6);
  EXPECT_GT(north.scale_at({-45.0, 60.0}).greatest, 1.03);
  EXPECT_LT(north.scale_at({-45.0, 85.0}).least, 0.975);            // (1 + sin 70) / (1 + sin 85) on the sphere: 0.9716
  const LocalFrame south = LocalFrame::from_user_crs("EPSG:3031");  // true at 71 S
  EXPECT_NEAR(south.scale_at({0.0, -71.0}).greatest, 1.0, 1e-6);
}

TEST(FrameScale, TheRuleRefusesDistortingFramesNamingTheFrameWhereAndHowMuch) {
  // Web Mercator at 35 N: every distance 22 % long.
  const std::string merc = refusal("EPSG:3857", around(9.0, 35.0));
  for (const char* w : {"the test area", "EPSG:3857", "stretches distances by 22.", "lat 35.0", "+proj=stere"})
    EXPECT_NE(merc.find(w), std::string::npos) << merc;
  EXPECT_EQ(merc.find('\n'), std::string::npos);
  EXPECT_NE(refusal("EPSG:3395", around(9.0, 35.0)), "");
  EXPECT_NE(refusal("EPSG:3832", around(179.0, 30.0)), "");  // PDC Mercator, true at the equator only
  EXPECT_NE(refusal("EPSG:3413", around(-45.0, 60.0)), "");
  EXPECT_NE(refusal("EPSG:3413", around(-45.0, 85.0)).find("shrinks distances"), std::string::npos);
  EXPECT_NE(refusal("EPSG:3031", around(0.0, -60.0)), "");
  // UTM 35N (central meridian 27 E) at 9 E, 54 N: 18 degrees off, 1.6 % long.
  EXPECT_NE(refusal("EPSG:32635", around(9.0, 54.0)).find("stretches distances by 1.6"), std::string::npos);
  // Kept: UTM within its zone, the polar frames at their standard parallels,
  // a stereographic centred on the area.
  EXPECT_EQ(refusal("EPSG:32632", around(9.0, 54.0)), "");
  EXPECT_EQ(refusal("EPSG:32632", around(11.5, 54.0)), "");
  EXPECT_EQ(refusal("EPSG:3413", around(-45.0, 70.0)), "");
  EXPECT_EQ(refusal("EPSG:3832", around(179.0, 0.5)), "");
  EXPECT_EQ(refusal(stereographic_crs_for(around(120.0, 88.0, 1.0)), around(120.0, 88.0, 1.0)), "");
}

TEST(FrameScale, ExtentsAcrossTheAntimeridianAreNarrowAndCentredThere) {
  const LonLatExtent e = extent_of({{179.5, -17.0}, {-179.6, -16.5}, {179.9, -16.8}});
  EXPECT_NEAR(e.west, 179.5, 1e-12);
  EXPECT_NEAR(e.east, 180.4, 1e-12);
  EXPECT_NEAR(e.centre().x(), 179.95, 1e-12);
  const LonLatExtent plain = extent_of({{10.0, 54.0}, {11.0, 55.0}});
  EXPECT_NEAR(plain.west, 10.0, 1e-12);
  EXPECT_NEAR(plain.east, 11.0, 1e-12);
  EXPECT_TRUE(extent_of({}).empty());
  // Fiji across the antimeridian: a UTM zone beside it, not zone 31 at lon 0.
  const LocalFrame f = default_frame_for(e);
  EXPECT_TRUE(f.id() == "EPSG:32760" || f.id() == "EPSG:32701") << f.id();
}

TEST(FrameScale, TheDefaultFrameIsUtmWhereItKeepsTheRuleElseAStereographicOnTheArea) {
  EXPECT_EQ(default_frame_for(around(10.2, 54.4)).id(), "EPSG:32632");
  // Beyond UTM's latitudes, and an area wider than a zone keeps true: a stereographic.
  const LonLatExtent pole = around(30.0, 88.0, 0.5);
  const LocalFrame polar = default_frame_for(pole);
  EXPECT_NE(polar.id().find("+proj=stere"), std::string::npos) << polar.id();
  EXPECT_EQ(refusal(polar.id(), pole), "");
  const LonLatExtent wide{0.0, 12.0, -1.0, 1.0};  // 12 degrees at the equator
  const LocalFrame w = default_frame_for(wide);
  EXPECT_NE(w.id().find("+proj=stere"), std::string::npos) << w.id();
  EXPECT_EQ(refusal(w.id(), around(6.0, 0.0, 0.5)), "");
}

TEST(FrameScale, AFrameInFeetIsRefusedBeforeItsScale) {
  try {
    LocalFrame::from_user_crs("+proj=utm +zone=32 +datum=WGS84 +units=us-ft");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("in metres"), std::string::npos) << e.what();
  }
}
