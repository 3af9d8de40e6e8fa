// The C++ side of bench/python_plan.py: the calls deepguide.plan makes
// (load_obstacles, parse_position, plan_route_request), in process, for each
// query of a file, so the Python module's overhead is the difference.
//   bench_plan_request OBSTACLES.csv QUERIES.txt CRS ROUNDS
// QUERIES.txt: one "x,y x,y" per line in CRS. Prints each query's median
// milliseconds over ROUNDS and its route length, one line per query.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/planning/route_plan_report.hpp"

int main(int argc, char** argv) {
  using namespace deepguide;
  if (argc != 5) {
    std::fprintf(stderr, "usage: bench_plan_request OBSTACLES.csv QUERIES.txt CRS ROUNDS\n");
    return 2;
  }
  const std::string obstacles = argv[1], crs = argv[3];
  const int rounds = std::max(1, std::atoi(argv[4]));
  std::ifstream in(argv[2]);
  std::string from, to;
  while (in >> from >> to) {
    std::vector<double> ms;
    double length = 0.0;
    for (int k = 0; k < rounds; ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      RoutePlanRequest r;
      LoadedObstacles loaded = load_obstacles({obstacles}, {crs, crs});
      r.obstacles = std::move(loaded.obstacles);
      r.problem.start = parse_position(from, "start", loaded.frame, true);
      r.problem.goal = parse_position(to, "goal", loaded.frame, true);
      try {
        length = plan_route_request(loaded.frame, r).route.length();
      } catch (const std::exception&) {
        length = -1.0;
      }
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
    std::printf("%.6f %.17g\n", ms[ms.size() / 2], length);
  }
}
