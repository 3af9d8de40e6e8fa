#pragma once
// Propulsion energy (docs/SIMULATION.md, "Vehicle model"): the power the vehicle
// draws at speed v through the water, P(v) = P_hotel + k v^3 (hotel load plus
// drag power, k = rho C_D A / (2 eta)). Defaults: k = 60 W/(m/s)^3 and
// P_hotel = 1050 W, which make v* = (P_hotel / 2k)^(1/3) = 2.06 m/s, DeepC's
// cruise (seed Table 1: 4 kn), the speed that spends least energy per metre
// in still water. Assumed values, to calibrate; both are vehicle-file keys.

#include <cmath>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

struct EnergyModel {
  double hotel_power_w = 1050.0;
  double propulsion_k_w_per_mps3 = 60.0;

  bool operator==(const EnergyModel&) const = default;

  /// P(v) in W.
  double power_w(double speed_mps) const {
    return hotel_power_w + propulsion_k_w_per_mps3 * speed_mps * speed_mps * speed_mps;
  }
  /// The still-water speed of least energy per metre, (P_hotel / 2k)^(1/3); +inf when k = 0.
  double economical_speed_mps() const { return std::cbrt(hotel_power_w / (2.0 * propulsion_k_w_per_mps3)); }
};

}  // namespace deepguide
