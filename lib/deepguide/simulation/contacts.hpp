#pragma once
// The simulation's memory of sonar contacts. The sonar reports only what is in
// its field of view now, and while rounding an obstacle the vehicle looks away
// from it; a reactive method fed only the last scan would forget the obstacle
// beside it. So each scan's detections are associated to remembered contacts,
// and the reactive method gets every remembered contact.
//
// Association never uses Detection::obstacle (the ground truth index): a real
// vehicle has only the estimates. Distance between a detection and a contact
// is the Hausdorff distance of the two ellipses. For convex sets it is
// exactly max over unit u of |h_A(u) - h_B(u)| (support functions), and for
// centrally symmetric sets h(+-u) = +-u.c + w(u), so
//   d_H = max over u in [0, pi) of |u.(c_A - c_B)| + |w_A(u) - w_B(u)|,
//   w(u) = sqrt(u^T S u)  (S the shape matrix),
// evaluated here at 16 directions 11.25 deg apart (a slight underestimate).
// Unlike a centre distance it tells apart two overlapping obstacles with one
// centre (a cross), and unlike comparing axes it does not care that the sonar
// swaps a and b of a near-circle. It is at least the centre distance, which
// prunes pairs cheaply.
//
// Gate: a detection may update a contact when d_H <= gate_m + 3 (s(r_c) +
// s(r_d)), with s(r) = position_sigma(r) + size_sigma(r) the sonar's noise
// scale at the range the contact was last seen at and at the detection's
// range (sonar.hpp). Exact detections (sigmas 0) gate at gate_m.
// Assignment is one-to-one per scan, greedy by increasing distance (ties: the
// lower contact, then the lower detection index): two obstacles seen in one
// scan never merge. An unmatched detection opens a new contact at the end of
// the list. A matched contact takes the newest estimate (the newest is the
// nearest while approaching, so the best). Contacts not seen for more than
// memory_s are forgotten (default: never, the obstacles are static);
// the order of the others is kept, so indices only shift down.
// No allocation once the buffers have grown to the largest scan.

#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/ellipse.hpp"
#include "deepguide/vehicle/sonar.hpp"

namespace DEEPGUIDE_API deepguide {

struct ContactParams {
  double gate_m = 2.0;                                        ///< association gate for exact detections (m)
  double memory_s = std::numeric_limits<double>::infinity();  ///< forget contacts unseen this long
};

/// Hausdorff distance of two ellipses, sampled at 16 directions (header).
double ellipse_hausdorff_distance(const Ellipse& a, const Ellipse& b);

class ContactMemory {
 public:
  ContactMemory(const ContactParams& params, const SonarParams& sonar);

  /// Associates one scan's detections made at `time_s`, then forgets stale contacts.
  void update(std::span<const Detection> detections, double time_s);

  /// The remembered estimates, oldest contact first.
  std::span<const Ellipse> ellipses() const { return ellipses_; }
  std::size_t size() const { return ellipses_.size(); }

 private:
  struct Pair {
    double distance;
    std::size_t contact, detection;
  };
  double noise_scale(double range_m) const;

  ContactParams params_;
  SonarParams sonar_;
  std::vector<Ellipse> ellipses_;
  std::vector<double> last_seen_s_;
  std::vector<double> noise_m_;  ///< s(r) at the range each contact was last seen
  std::vector<Pair> pairs_;
  std::vector<char> contact_taken_, detection_taken_;
};

}  // namespace deepguide
