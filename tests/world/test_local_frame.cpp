// The local metric frame: UTM zone choice, projections, and true north.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/world/local_frame.hpp"

using namespace deepguide;

TEST(UtmZone, PicksZoneAndHemisphereFromLonLat) {
  EXPECT_EQ(utm_epsg_for(10.25, 54.45), 32632);   // Kiel Bight
  EXPECT_EQ(utm_epsg_for(-81.86, 24.56), 32617);  // Key West
  EXPECT_EQ(utm_epsg_for(151.2, -33.9), 32756);   // Sydney, south
  EXPECT_EQ(utm_epsg_for(-180.0, 10.0), 32601);
  EXPECT_EQ(utm_epsg_for(179.999, 10.0), 32660);
  EXPECT_EQ(utm_epsg_for(180.0, 10.0), 32601);  // the antimeridian wraps
  EXPECT_EQ(utm_epsg_for(6.0, 0.0), 32632);     // zone edges belong to the east zone
}

TEST(LocalFrame, CentralMeridianOnTheEquatorIsTheFalseEasting) {
  const LocalFrame f = LocalFrame::from_user_crs("EPSG:32632");
  const Eigen::Vector2d xy = f.from_lonlat(9.0, 0.0);
  EXPECT_NEAR(xy.x(), 500000.0, 1e-6);
  EXPECT_NEAR(xy.y(), 0.0, 1e-6);
  EXPECT_EQ(f.id(), "EPSG:32632");
  EXPECT_NE(f.name().find("UTM zone 32N"), std::string::npos);
}

TEST(LocalFrame, OneDegreeOfLatitudeOnTheCentralMeridian) {
  // Meridian arc from 0 to 1 deg N on WGS 84 is 110574.389 m; UTM scales it by k0 = 0.9996.
  const LocalFrame f = LocalFrame::from_user_crs("EPSG:32632");
  EXPECT_NEAR(f.from_lonlat(9.0, 1.0).y(), 0.9996 * 110574.389, 0.01);
}

TEST(LocalFrame, LonLatRoundTripIsExact) {
  const LocalFrame f = LocalFrame::utm_for(10.25, 54.45);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> lon(7.0, 12.0), lat(50.0, 58.0);
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector2d ll(lon(rng), lat(rng));
    const Eigen::Vector2d back = f.to_lonlat(f.from_lonlat(ll));
    EXPECT_NEAR(back.x(), ll.x(), 1e-10);
    EXPECT_NEAR(back.y(), ll.y(), 1e-10);
  }
}

TEST(LocalFrame, TrueNorthFollowsTheMeridianConvergence) {
  const LocalFrame f = LocalFrame::from_user_crs("EPSG:32632");
  // On the central meridian true north is grid north.
  EXPECT_NEAR(f.true_north_angle(f.from_lonlat(9.0, 54.0)), kPi / 2, 1e-9);
  // East of it, in the north, meridians lean towards the central meridian:
  // gamma = atan(tan(dlon) sin(lat)) to first order, true north turned anticlockwise.
  const double lat = 54.45;
  const double gamma = std::atan(std::tan(deg_to_rad(3.0)) * std::sin(deg_to_rad(lat)));
  EXPECT_NEAR(f.true_north_angle(f.from_lonlat(12.0, lat)) - kPi / 2, gamma, deg_to_rad(0.01));
  EXPECT_NEAR(f.true_north_angle(f.from_lonlat(6.0, lat)) - kPi / 2, -gamma, deg_to_rad(0.01));
}

TEST(LocalFrame, HeadingConversionsAreInverse) {
  const LocalFrame f = LocalFrame::utm_for(10.25, 54.45);
  const Eigen::Vector2d p = f.from_lonlat(11.5, 55.0);
  for (double h : {0.0, 30.0, 90.0, 179.5, 270.0, 359.9}) {
    EXPECT_NEAR(f.local_to_heading(f.heading_to_local(h, p), p), h, 1e-9);
  }
  // At the central meridian heading 0 is +y and heading 90 is +x.
  const Eigen::Vector2d c = f.from_lonlat(9.0, 40.0);
  EXPECT_NEAR(f.heading_to_local(0.0, c), kPi / 2, 1e-9);
  EXPECT_NEAR(f.heading_to_local(90.0, c), 0.0, 1e-9);
}

TEST(LocalFrame, UnknownCrsIsAnInputErrorNamingTheOption) {
  try {
    LocalFrame::from_user_crs("EPSG:999999", "--crs");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--crs"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("EPSG:999999"), std::string::npos) << e.what();
  }
  EXPECT_THROW(LocalFrame::from_user_crs("not a crs at all"), InputError);
  EXPECT_THROW(LocalFrame::from_user_crs(""), InputError);
}

TEST(LocalFrame, GeographicCrsIsRefusedAsPlanningFrame) {
  try {
    LocalFrame::from_user_crs("EPSG:4326", "--crs");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("projected"), std::string::npos) << e.what();
  }
}

// Issue 39: a frame in feet took a 5 m margin as 5 ft (plan passed 15.9 m inside an obstacle with
// +units=us-ft) and `obstacles info --crs EPSG:2229` printed feet as metres.
TEST(LocalFrame, AFrameNotInMetresIsRefusedNamingItsUnit) {
  for (const char* crs :
       {"+proj=utm +zone=32 +datum=WGS84 +units=us-ft", "EPSG:2229", "+proj=utm +zone=32 +units=km"}) {
    try {
      LocalFrame::from_user_crs(crs, "--crs");
      FAIL() << crs << ": no error";
    } catch (const InputError& e) {
      const std::string why = e.what();
      EXPECT_NE(why.find("--crs: expected a projected CRS in metres"), std::string::npos) << why;
      EXPECT_NE(why.find(crs), std::string::npos) << why;
    }
  }
  EXPECT_NO_THROW(LocalFrame::from_user_crs("+proj=utm +zone=32 +datum=WGS84 +units=m"));
  EXPECT_NO_THROW(LocalFrame::from_user_crs("EPSG:3413"));
}

// Issue 39: a WKT with a typo in its projection method was read, and every
// position then failed to project: the first obstacle was blamed ("expected a
// position inside the area of the local frame"). The frame itself is refused.
TEST(LocalFrame, AProjectionMethodPROJDoesNotKnowIsRefusedAsTheFrame) {
  const std::string typo =
      R"(PROJCS["WGS 84 / UTM zone 32N",GEOGCS["WGS 84",DATUM["WGS_1984",SPHEROID["WGS 84",6378137,298.257223563]],)"
      R"(PRIMEM["Greenwich",0],UNIT["degree",0.0174532925199433]],PROJECTION["Transverse_Mercatorr"],)"
      R"(PARAMETER["latitude_of_origin",0],PARAMETER["central_meridian",9],PARAMETER["scale_factor",0.9996],)"
      R"(PARAMETER["false_easting",500000],PARAMETER["false_northing",0],UNIT["metre",1]])";
  try {
    LocalFrame::from_user_crs(typo, "--crs");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string why = e.what();
    EXPECT_NE(why.find("--crs: 'PROJCS[\"WGS 84 / UTM zone 32N\""), std::string::npos) << why;
    EXPECT_NE(why.find("projects no position (projection method 'Transverse_Mercatorr')"), std::string::npos) << why;
    EXPECT_EQ(why.find('\n'), std::string::npos) << why;
  }
  // The same WKT spelt right, and frames whose origin is a pole or far from the equator, are kept.
  std::string right = typo;
  right.replace(right.find("Mercatorr"), 9, "Mercator");
  EXPECT_EQ(LocalFrame::from_user_crs(right).name(), "WGS 84 / UTM zone 32N");
  for (const char* crs : {"EPSG:3031", "EPSG:3413", "+proj=stere +lat_0=90 +lon_0=-45 +datum=WGS84 +units=m",
                          "+proj=ortho +lat_0=54 +lon_0=10 +datum=WGS84 +units=m", "EPSG:3832", "EPSG:5041"}) {
    EXPECT_NO_THROW(LocalFrame::from_user_crs(crs)) << crs;
  }
}
