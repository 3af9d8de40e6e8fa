// Route files in (planning/route_io.hpp): RTZ routes from an ECDIS (the
// Norwegian Coastal Administration's published routes, namespace
// https://cirm.org/rtz-xml-schemas) and OpenCPN's GPX read with every
// waypoint, each position equal to the file's own (read here with libxml2
// XPath, independently of the reader); hostile RTZ files are one-line errors.
#include <gtest/gtest.h>
#include <libxml/parser.h>
#include <libxml/xpath.h>

#include <string>
#include <vector>

#include "deepguide/core/error.hpp"
#include "deepguide/planning/route_io.hpp"
#include "test_support.hpp"

using namespace deepguide;
using deepguide::test::ScratchDir;

namespace {

// Every value the XPath selects (attributes' values), with local-name() so any namespace matches.
std::vector<double> xpath_numbers(const std::string& path, const std::string& xpath) {
  std::vector<double> out;
  xmlDocPtr doc = xmlReadFile(path.c_str(), nullptr, XML_PARSE_NONET);
  if (doc == nullptr) return out;
  xmlXPathContextPtr ctx = xmlXPathNewContext(doc);
  xmlXPathObjectPtr r = xmlXPathEvalExpression(reinterpret_cast<const xmlChar*>(xpath.c_str()), ctx);
  if (r && r->nodesetval) {
    for (int i = 0; i < r->nodesetval->nodeNr; ++i) {
      xmlChar* v = xmlNodeGetContent(r->nodesetval->nodeTab[i]);
      out.push_back(std::stod(reinterpret_cast<const char*>(v)));
      xmlFree(v);
    }
  }
  xmlXPathFreeObject(r);
  xmlXPathFreeContext(ctx);
  xmlFreeDoc(doc);
  return out;
}

void expect_same_positions(const std::string& path, const std::vector<RouteFileWaypoint>& got,
                           const std::string& lon_xpath, const std::string& lat_xpath, std::size_t count) {
  const std::vector<double> lon = xpath_numbers(path, lon_xpath), lat = xpath_numbers(path, lat_xpath);
  ASSERT_EQ(lon.size(), count) << path;  // the count grep and xmllint give for the file
  ASSERT_EQ(got.size(), count) << path;
  for (std::size_t i = 0; i < count; ++i) {
    EXPECT_NEAR(got[i].lonlat.x(), lon[i], 1e-9) << path << " " << i;
    EXPECT_NEAR(got[i].lonlat.y(), lat[i], 1e-9) << path << " " << i;
  }
}

}  // namespace

TEST(RouteFiles, NcaRtzRoutesReadEveryWaypoint) {
  const std::string wpt = "/*[local-name()='route']/*[local-name()='waypoints']/*[local-name()='waypoint']";
  const std::string pos = wpt + "/*[local-name()='position']";
  const std::vector<std::pair<std::string, std::size_t>> routes = {
      {"rtz-nca-norway/NCA_7_5m_Bergen_Stad_Krakhelle_In_20250731.rtz", 82},
      {"rtz-nca-norway/NCA_Bergen_Fedjeosen_In_20250801.rtz", 18},
      {"rtz-nca-norway/NCA_OsloEast_In_20250731.rtz", 18}};
  for (const auto& [rel, count] : routes) {
    DEEPGUIDE_REAL_FILE_OR_SKIP(path, rel);
    const std::vector<RouteFileWaypoint> got = read_route_waypoints(path);
    expect_same_positions(path, got, pos + "/@lon", pos + "/@lat", count);
    EXPECT_FALSE(got.front().name.empty()) << path;  // NCA names every waypoint
  }
  DEEPGUIDE_REAL_FILE_OR_SKIP(bergen, "rtz-nca-norway/NCA_7_5m_Bergen_Stad_Krakhelle_In_20250731.rtz");
  EXPECT_EQ(read_route_waypoints(bergen).front().name, "Stalet");
}

TEST(RouteFiles, OpenCpnGpxReadsEveryRoutePoint) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, "opencpn-gpx/opencpn_route_foo.gpx");
  const std::string pt = "//*[local-name()='rte']/*[local-name()='rtept']";
  expect_same_positions(path, read_route_waypoints(path), pt + "/@lon", pt + "/@lat", 13);
}

TEST(RouteFiles, HostileRtzIsAOneLineError) {
  ScratchDir dir;
  const std::string head =
      "<?xml version=\"1.0\"?><route xmlns=\"http://www.cirm.org/RTZ/1/0\" version=\"1.0\">"
      "<routeInfo routeName=\"x\"/><waypoints>";
  const std::string ok = "<waypoint id=\"1\"><position lat=\"60\" lon=\"5\"/></waypoint>";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"<route", "could not parse"},
      {"<?xml version=\"1.0\"?><gpx/>", "<route>"},
      {head + ok + "</waypoints></route>", "at least 2 waypoints"},
      {head + ok + "<waypoint id=\"2\"><position lat=\"95\" lon=\"5\"/></waypoint></waypoints></route>",
       "waypoint 2: field 'lat'"},
      {head + ok + "<waypoint id=\"7\"><position lat=\"60\" lon=\"east\"/></waypoint></waypoints></route>",
       "waypoint 7: field 'lon'"},
      {head + ok + "<waypoint id=\"3\"></waypoint></waypoints></route>", "waypoint 3: expected a <position"},
  };
  for (const auto& [text, says] : cases) {
    const std::string path = dir.write("bad.rtz", text);
    try {
      read_route_waypoints(path);
      ADD_FAILURE() << text;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(says), std::string::npos) << what;
      EXPECT_NE(what.find("bad.rtz"), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
  EXPECT_THROW(read_route_waypoints(dir.file("missing.rtz")), InputError);
}

// A CSV of waypoints holds each position twice, as WKT and as lon, lat (as
// `mission export` writes it): a file whose two disagree is refused, since
// GDAL reads the WKT and drops the rest without a word (issue 39).
TEST(RouteFiles, ACsvWhoseWktAndLonLatDisagreeIsRefused) {
  ScratchDir dir;
  const std::string agree =
      dir.write("ok.csv", "WKT,name,lon,lat\n\"POINT (10 54)\",001,10,54\n\"POINT (10.01 54)\",002,10.01,54\n");
  const std::vector<RouteFilePart> parts = read_route_parts(agree);
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts.front().points.size(), 2u);
  const std::string apart =
      dir.write("apart.csv", "WKT,name,lon,lat\n\"POINT (10 54)\",001,10,54\n\"POINT (10.01 54)\",002,10.03,54\n");
  try {
    read_route_parts(apart);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    for (const char* w : {"apart.csv", "'lon', 'lat' (10.03, 54)", "geometry (10.01, 54)", "one position"})
      EXPECT_NE(what.find(w), std::string::npos) << what;
  }
}

// A CSV of waypoints in lon and lat columns is read (it was "expected a route
// line or points, found none"); a row without a finite position is a hole in
// the route, refused naming its line and columns, never skipped (issue 39:
// NaN in a file's fields).
TEST(RouteFiles, ACsvOfLonLatIsReadAndARowWithoutAFinitePositionIsRefused) {
  ScratchDir dir;
  const std::vector<RouteFilePart> parts =
      read_route_parts(dir.write("lonlat.csv", "name,Lat,Lon\na,54.0,10.0\nb,54.001,10.002\nc,54.002,10.0\n"));
  ASSERT_EQ(parts.size(), 1u);  // the points, joined in file order into the route
  ASSERT_EQ(parts[0].points.size(), 3u);
  EXPECT_DOUBLE_EQ(parts[0].points[1].lonlat.x(), 10.002);
  EXPECT_DOUBLE_EQ(parts[0].points[1].lonlat.y(), 54.001);
  const std::vector<std::pair<std::string, std::vector<std::string>>> bad = {
      {"lon,lat\n10,54\nnan,54.001\n", {"line 3", "fields 'lon', 'lat'", "no finite number and '54.001'"}},
      {"lon,lat\n10,54\n10.002,inf\n", {"line 3", "'10.002' and no finite number"}},
      {"lon,lat\n10,54\n10.002,\n", {"line 3", "no finite number"}},
      {"lon,lat\n10,54\n10.002,-inf\n10,54.002\n", {"line 3"}},
      {"x,y\n10,54\n10.002,54.001\n", {"line 1", "column 'x'", "lon and lat columns"}},
      {"name,depth\na,4\nb,5\n", {"line 1", "a WKT column, or lon and lat columns"}},
      {"lon,longitude,lat\n10,10,54\n", {"line 1", "expected one column of", "lon and longitude"}},
      {"WKT,lon,lat\n\"POINT (10 54)\",10,54\n\"POINT (nan 54)\",10,54\n", {"line 3", "field 'wkt'"}},
  };
  for (const auto& [text, words] : bad) {
    const std::string path = dir.write("bad.csv", text);
    try {
      read_route_parts(path);
      ADD_FAILURE() << text << ": accepted";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
      for (const std::string& w : words) EXPECT_NE(what.find(w), std::string::npos) << text << ": " << what;
    }
  }
}
