// The vehicle model against closed forms (Nomoto step, turn radius, straight
// run in a current, speed and depth lags), its limits, determinism, and the
// vehicle file reader with good and bad files.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>

#include "deepguide/core/error.hpp"
#include "deepguide/vehicle/vehicle_model.hpp"
#include "deepguide/vehicle/vehicle_params.hpp"
#include "test_support.hpp"

using namespace deepguide;
using deepguide::test::ScratchDir;

namespace {

const VehicleParams kP{};

VehicleState run(VehicleState s, const VehicleCommand& c, int steps, const Vec2& current = Vec2::Zero()) {
  for (int i = 0; i < steps; ++i) step_vehicle(kP, s, c, current);
  return s;
}

}  // namespace

TEST(VehicleModel, DefaultsAreTheDocumentedDeepCNumbers) {
  EXPECT_NEAR(kP.cruise_speed_mps, 2.057778, 1e-6);  // 4 kn
  EXPECT_NEAR(kP.max_speed_mps, 3.086667, 1e-6);     // 6 kn
  // r_ss = K delta_max = 0.25 x 25 deg = 6.25 deg/s, above the 6 deg/s limit.
  EXPECT_NEAR(rad_to_deg(kP.nomoto_gain_per_s * kP.max_rudder), 6.25, 1e-12);
  EXPECT_DOUBLE_EQ(kP.step_s, 0.1);
}

TEST(VehicleModel, NomotoStepResponseMatchesClosedForm) {
  // Rudder already at 5 deg and held there: r(t) = K d (1 - exp(-t/T)),
  // psi(t) = psi0 + K d (t - T (1 - exp(-t/T))). RK4's error is about
  // K d (h/T)^4 / 120 = 7e-11 rad/s; 1e-9 leaves room for rounding.
  const double d = deg_to_rad(5.0), K = kP.nomoto_gain_per_s, T = kP.nomoto_time_constant_s;
  VehicleState s = make_vehicle_state({0, 0}, 10.0, 0.0, kP.cruise_speed_mps);
  s.rudder = d;
  const VehicleCommand c{d, kP.cruise_speed_mps, 10.0};
  for (int i = 1; i <= 300; ++i) {
    step_vehicle(kP, s, c, Vec2::Zero());
    const double t = i * kP.step_s;
    ASSERT_NEAR(s.yaw_rate, K * d * (1.0 - std::exp(-t / T)), 1e-9) << "t = " << t;
    ASSERT_NEAR(s.heading, K * d * (t - T * (1.0 - std::exp(-t / T))), 1e-8) << "t = " << t;
    ASSERT_EQ(s.rudder, d);
    if (i == 40) {
      // 63 % at t = T; RK4's relative error there is 40 steps x (h/T)^5/120 x e^-1 / (1 - e^-1) = 1.2e-9.
      EXPECT_NEAR(s.yaw_rate / (K * d), 1.0 - std::exp(-1.0), 2e-9);
    }
  }
  EXPECT_GT(s.yaw_rate, 0.0);  // positive rudder turns counter-clockwise (to port)
}

TEST(VehicleModel, RudderAndTurnRateLimitsHold) {
  VehicleState s = make_vehicle_state({0, 0}, 0.0, 0.0, kP.cruise_speed_mps);
  const VehicleCommand c{deg_to_rad(-40.0), kP.cruise_speed_mps, 0.0};  // beyond the 25 deg stop
  double max_r = 0.0;
  for (int i = 0; i < 600; ++i) {
    const double before = s.rudder;
    step_vehicle(kP, s, c, Vec2::Zero());
    ASSERT_LE(std::abs(s.rudder), kP.max_rudder);
    ASSERT_LE(std::abs(s.rudder - before), kP.max_rudder_rate * kP.step_s * (1 + 1e-12));
    ASSERT_LE(std::abs(s.yaw_rate), kP.max_turn_rate);
    max_r = std::max(max_r, std::abs(s.yaw_rate));
  }
  EXPECT_DOUBLE_EQ(s.rudder, -kP.max_rudder);
  // K delta_max = 6.25 deg/s would be the Nomoto steady state; the limit caps it at 6.
  EXPECT_DOUBLE_EQ(max_r, kP.max_turn_rate);
  EXPECT_DOUBLE_EQ(s.yaw_rate, -kP.max_turn_rate);  // negative rudder: clockwise
  // The rudder needs 25 deg / 10 deg/s = 2.5 s at its rate limit: not there after 2 s.
  VehicleState q = run(make_vehicle_state({0, 0}, 0.0, 0.0, 2.0), c, 20);
  EXPECT_GT(q.rudder, -kP.max_rudder + deg_to_rad(4.0));
}

TEST(VehicleModel, SteadyTurnRadiusIsSpeedOverTurnRate) {
  const VehicleCommand c{kP.max_rudder, kP.cruise_speed_mps, 0.0};
  VehicleState s = run(make_vehicle_state({100, -50}, 0.0, 0.3, kP.cruise_speed_mps), c, 600);
  ASSERT_DOUBLE_EQ(s.yaw_rate, kP.max_turn_rate);
  const double radius = s.speed_mps / s.yaw_rate;  // 2.0578 / 0.10472 = 19.65 m
  EXPECT_NEAR(radius, 19.650, 1e-3);
  const Vec2 centre = s.position + radius * unit_vector(s.heading + kPi / 2.0);  // turning to port
  for (int i = 0; i < 600; ++i) {
    step_vehicle(kP, s, c, Vec2::Zero());
    ASSERT_NEAR((s.position - centre).norm(), radius, 1e-7) << "step " << i;
  }
}

TEST(VehicleModel, StraightRunInUniformCurrentIsExact) {
  const Vec2 current(0.3, -0.2);
  const double heading = heading_deg_to_math_rad(30.0);
  const Vec2 start(1000.0, 2000.0);
  VehicleState s = make_vehicle_state(start, 50.0, heading, kP.cruise_speed_mps, current);
  const VehicleCommand c{0.0, kP.cruise_speed_mps, 50.0};
  s = run(s, c, 1000, current);
  const double t = 1000 * kP.step_s;
  EXPECT_NEAR(s.time_s, 100.0, 1e-10);
  const Vec2 expected = start + (kP.cruise_speed_mps * vector_of_course_deg(30.0) + current) * t;
  EXPECT_NEAR(s.position.x(), expected.x(), 1e-9);
  EXPECT_NEAR(s.position.y(), expected.y(), 1e-9);
  EXPECT_EQ(s.heading, heading);
  EXPECT_NEAR(s.depth_m, 50.0, 0.0);
  // Course over ground differs from the heading by the current's set only.
  const Vec2 g = kP.cruise_speed_mps * vector_of_course_deg(30.0) + current;
  EXPECT_NEAR(math_rad_to_heading_deg(course_over_ground(s)), course_deg_of(g), 1e-9);
  EXPECT_GT(std::abs(math_rad_to_heading_deg(course_over_ground(s)) - 30.0), 5.0);
}

TEST(VehicleModel, CurrentFieldSampledAtTheStages) {
  // A uniform field must give the very same bits as the Vec2 overload ...
  const Vec2 c0(0.2, 0.1);
  VehicleState a = make_vehicle_state({0, 0}, 0.0, 1.0, 1.5), b = a;
  const VehicleCommand cmd{deg_to_rad(3.0), 2.0, 20.0};
  const CurrentFunction uniform = [&](const Vec2&, double, double) { return c0; };
  for (int i = 0; i < 200; ++i) {
    step_vehicle(kP, a, cmd, c0);
    step_vehicle(kP, b, cmd, uniform);
  }
  EXPECT_EQ(a, b);
  // ... and a shear c = (0, k x) at rest (u = 0) moves a parcel along y by k x t with x fixed.
  const double k = 0.01;
  const CurrentFunction shear = [k](const Vec2& p, double, double) { return Vec2(0.0, k * p.x()); };
  VehicleState s = make_vehicle_state({50, 0}, 0.0, 0.0, 0.0);
  for (int i = 0; i < 100; ++i) step_vehicle(kP, s, VehicleCommand{0, 0, 0}, shear);
  EXPECT_NEAR(s.position.y(), k * 50 * 10.0, 1e-12);
  EXPECT_NEAR(s.ground_velocity.y(), 0.5, 1e-12);
}

TEST(VehicleModel, SpeedReachesSetPointWithItsTimeConstant) {
  VehicleState s = make_vehicle_state({0, 0}, 0.0, 0.0, 0.0);
  const double Tu = kP.speed_time_constant_s;
  for (int i = 1; i <= 600; ++i) {
    step_vehicle(kP, s, VehicleCommand{0, 3.0, 0}, Vec2::Zero());
    ASSERT_NEAR(s.speed_mps, 3.0 * (1.0 - std::exp(-i * kP.step_s / Tu)), 1e-9);
  }
  // Asking for more than the maximum: approaches 6 kn, never passes it.
  for (int i = 0; i < 3000; ++i) {
    step_vehicle(kP, s, VehicleCommand{0, 50.0, 0}, Vec2::Zero());
    ASSERT_LE(s.speed_mps, kP.max_speed_mps);
  }
  EXPECT_NEAR(s.speed_mps, kP.max_speed_mps, 1e-5);
  // Astern is not a speed set-point: it slows to a stop.
  s = run(s, VehicleCommand{0, -3.0, 0}, 3000);
  EXPECT_GE(s.speed_mps, 0.0);
  EXPECT_LT(s.speed_mps, 1e-5);
}

TEST(VehicleModel, DepthFollowsLagThenRateLimit) {
  // Small step (2 m / 10 s = 0.2 m/s < 0.5 m/s): the plain lag 2 (1 - exp(-t/10)).
  VehicleState s = make_vehicle_state({0, 0}, 0.0, 0.0, 2.0);
  for (int i = 1; i <= 300; ++i) {
    step_vehicle(kP, s, VehicleCommand{0, 2.0, 2.0}, Vec2::Zero());
    ASSERT_NEAR(s.depth_m, 2.0 * (1.0 - std::exp(-i * kP.step_s / kP.depth_time_constant_s)), 1e-9);
  }
  // Large step 0 -> 100 m: 0.5 m/s until 5 m short (t = 190 s), then the lag.
  s = make_vehicle_state({0, 0}, 0.0, 0.0, 2.0);
  for (int i = 1; i <= 2500; ++i) {
    const double before = s.depth_m;
    step_vehicle(kP, s, VehicleCommand{0, 2.0, 100.0}, Vec2::Zero());
    ASSERT_LE(s.depth_m - before, kP.max_vertical_speed_mps * kP.step_s + 1e-12);
    if (i == 1000) {
      EXPECT_NEAR(s.depth_m, 50.0, 1e-9);
    }
    if (i == 2500) {
      EXPECT_NEAR(s.depth_m, 100.0 - 5.0 * std::exp(-6.0), 1e-3);
    }
  }
  // Above the surface is not a depth.
  s = run(s, VehicleCommand{0, 2.0, -30.0}, 3000);
  EXPECT_GE(s.depth_m, 0.0);
  EXPECT_LT(s.depth_m, 1e-3);
}

TEST(VehicleModel, SameInputsGiveBitIdenticalStates) {
  auto simulate = [](double cx) {
    const CurrentFunction current = [cx](const Vec2& p, double z, double t) {
      return Vec2(cx + 0.001 * p.y(), 0.1 * std::sin(0.01 * t) + 0.0001 * z);
    };
    VehicleState s = make_vehicle_state({3, 4}, 5.0, 0.7, 1.0);
    for (int i = 0; i < 5000; ++i) {
      const VehicleCommand c{deg_to_rad(30.0 * std::sin(0.003 * i)), 1.0 + 0.002 * (i % 1000), 0.01 * i};
      step_vehicle(kP, s, c, current);
    }
    return s;
  };
  const VehicleState a = simulate(0.2), b = simulate(0.2), c = simulate(0.2 + 1e-12);
  EXPECT_EQ(a, b);
  EXPECT_FALSE(a == c);  // the comparison sees a 1e-12 m/s change of the current
}

// ---------------------------------------------------------------------------
// Vehicle files

namespace {

std::string error_of(const std::string& text, const std::string& name = "v.yaml") {
  try {
    parse_vehicle_yaml(text, name);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

using deepguide::test::expect_error;

}  // namespace

TEST(VehicleFile, BundledDeepCFileIsTheDefaults) {
  const VehicleParams p = read_vehicle_file(deepguide::test::source_file("data/vehicles/deepc.yaml"));
  EXPECT_EQ(p, VehicleParams{});
  EXPECT_EQ(parse_vehicle_yaml("{}", "empty-map"), VehicleParams{});
}

TEST(VehicleFile, WrittenParametersReadBack) {
  EXPECT_EQ(parse_vehicle_yaml(vehicle_yaml(VehicleParams{}), "defaults"), VehicleParams{});
  VehicleParams p;
  p.name = "Tiny: AUV # with ' odd \" chars";
  p.cruise_speed_mps = 1.234567890123;
  p.max_speed_mps = 2.5;
  p.nomoto_gain_per_s = 0.4;
  p.max_rudder = 0.3;
  p.max_turn_rate = 0.1;  // < K x max_rudder = 0.12
  p.step_s = 0.05;
  p.autopilot.max_reference_turn_rate = 0.07;
  const VehicleParams q = parse_vehicle_yaml(vehicle_yaml(p), "custom");
  EXPECT_EQ(q.name, p.name);
  EXPECT_EQ(q.cruise_speed_mps, p.cruise_speed_mps);
  EXPECT_NEAR(q.max_rudder, p.max_rudder, 1e-15);  // radians -> degrees -> radians
  EXPECT_NEAR(q.autopilot.max_reference_turn_rate, 0.07, 1e-15);
  EXPECT_EQ(q.step_s, 0.05);
}

TEST(VehicleFile, SpeedsInKnotsOrMetresPerSecond) {
  const VehicleParams p = parse_vehicle_yaml("cruise_speed_mps: 1.5\nmax_speed_kn: 5\n", "s.yaml");
  EXPECT_EQ(p.cruise_speed_mps, 1.5);
  EXPECT_NEAR(p.max_speed_mps, 5 * 1852.0 / 3600.0, 1e-15);
  expect_error(error_of("cruise_speed_mps: 1.5\ncruise_speed_kn: 3\n"),
               {"v.yaml", "line 2", "cruise_speed_kn", "one unit only", "cruise_speed_mps"});
}

TEST(VehicleFile, UnknownKeyNamesLineAndKey) {
  expect_error(error_of("length_m: 5\n\nmax_sped_kn: 6\n"), {"v.yaml", "line 3", "max_sped_kn", "known keys"});
  expect_error(error_of("autopilot:\n  damping: 0.7\n"), {"line 2", "autopilot.damping", "known keys"});
}

TEST(VehicleFile, OutOfRangeValues) {
  expect_error(error_of("name: x\nmax_speed_kn: -6\n"), {"v.yaml", "line 2", "max_speed_kn", "> 0", "got -6"});
  expect_error(error_of("nomoto_time_constant_s: 0\n"), {"line 1", "nomoto_time_constant_s", "> 0"});
  expect_error(error_of("max_rudder_deg: 120\n"), {"line 1", "max_rudder_deg", "<= 90", "got 120"});
  expect_error(error_of("step_s: 0.4\n"), {"line 1", "step_s", "half the smallest time constant (0.25 s)"});
  // A step that only multiplies the work (1e-9 s ran for minutes and gigabytes).
  expect_error(error_of("step_s: 1e-9\n"), {"line 1", "step_s", ">= 0.001 s", "got 1e-09"});
  EXPECT_EQ(error_of("step_s: 0.001\n"), "");
  expect_error(error_of("autopilot:\n  max_reference_turn_rate_deg_s: 7\n"),
               {"line 2", "autopilot.max_reference_turn_rate_deg_s", "6 deg/s"});
}

TEST(VehicleFile, EnergyKeysAndMinimumSpeed) {
  const VehicleParams p =
      parse_vehicle_yaml("hotel_power_w: 800\npropulsion_k_w_per_mps3: 45.5\nmin_speed_kn: 2\n", "e.yaml");
  EXPECT_EQ(p.energy.hotel_power_w, 800.0);
  EXPECT_EQ(p.energy.propulsion_k_w_per_mps3, 45.5);
  EXPECT_NEAR(p.min_speed_mps, 2 * 1852.0 / 3600.0, 1e-15);
  EXPECT_EQ(parse_vehicle_yaml(vehicle_yaml(p), "again"), p);
  // Negative or zero power coefficients are refused, naming line and key.
  expect_error(error_of("name: x\nhotel_power_w: -10\n"), {"v.yaml", "line 2", "hotel_power_w", "> 0", "got -10"});
  expect_error(error_of("propulsion_k_w_per_mps3: -60\n"), {"line 1", "propulsion_k_w_per_mps3", "> 0", "got -60"});
  expect_error(error_of("propulsion_k_w_per_mps3: 0\n"), {"line 1", "propulsion_k_w_per_mps3", "> 0"});
  expect_error(error_of("min_speed_kn: 5\n"), {"line 1", "min_speed_kn", "<= cruise_speed_mps", "got 5"});
}

TEST(VehicleFile, CruiseAboveMaxSpeed) {
  expect_error(error_of("max_speed_kn: 6\n# faster than max\ncruise_speed_kn: 7\n"),
               {"v.yaml", "line 3", "cruise_speed_kn", "<= max_speed_kn (6)", "got 7"});
  // The default max (6 kn) applies when the file gives only the cruise speed.
  expect_error(error_of("cruise_speed_mps: 4\n"), {"line 1", "cruise_speed_mps", "max_speed_mps"});
}

TEST(VehicleFile, WrongTypes) {
  expect_error(error_of("mass_kg: heavy\n"), {"v.yaml", "line 1", "mass_kg", "a number", "'heavy'"});
  expect_error(error_of("mass_kg: [1, 2]\n"), {"line 1", "mass_kg", "a list or mapping"});
  expect_error(error_of("length_m: .nan\n"), {"line 1", "length_m", "finite"});
  expect_error(error_of("length_m: .inf\n"), {"line 1", "length_m", "finite"});
  expect_error(error_of("autopilot: 3\n"), {"line 1", "autopilot", "mapping"});
  expect_error(error_of("name: [a]\n"), {"line 1", "name", "text"});
  expect_error(error_of("length_m: 5\nlength_m: 6\n"), {"line 2", "length_m", "duplicate", "line 1"});
}

TEST(VehicleFile, NotAVehicleFile) {
  expect_error(error_of(""), {"v.yaml", "mapping", "empty"});
  expect_error(error_of("- 1\n- 2\n"), {"v.yaml", "line 1", "mapping"});
  expect_error(error_of("length_m: 5\n  bad: [unclosed\n"), {"v.yaml", "line 2", "YAML"});
  expect_error(error_of("a: \x01\x02\n"), {"v.yaml"});
  expect_error(error_of(std::string(5000, '[')), {"v.yaml"});  // deep nesting: an error, not a stack overflow
  ScratchDir dir;
  const std::string missing = dir.file("none.yaml");
  try {
    read_vehicle_file(missing);
    FAIL() << "no error for a missing file";
  } catch (const InputError& e) {
    expect_error(e.what(), {missing.c_str(), "existing"});
  }
  const std::string f = dir.write("bad.yaml", "max_speed_kn: -1\n");
  try {
    read_vehicle_file(f);
    FAIL() << "no error for a bad file";
  } catch (const InputError& e) {
    expect_error(e.what(), {f.c_str(), "line 1", "max_speed_kn"});
  }
}

TEST(VehicleFile, ValidateProgrammaticParameters) {
  VehicleParams p;
  EXPECT_NO_THROW(validate(p));
  p.max_speed_mps = std::nan("");
  expect_error(
      [&] {
        try {
          validate(p, "scenario.yaml");
        } catch (const InputError& e) {
          return std::string(e.what());
        }
        return std::string();
      }(),
      {"scenario.yaml", "max_speed_mps"});
}
