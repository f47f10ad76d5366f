// The walls under a spreading arch (spreading.hpp), private to the limit module: the walls turn about
// their bases' outer toes as rigid bodies, carrying the springing joints on their tops by exact rigid
// motions; the arch's ring without the walls, on which the path is followed; and whether the walls carry
// each state (the resultant down each wall inside every bed, and with friction inside its cone).
#pragma once

#include <limits>
#include <optional>
#include <vector>

#include "limit/spreading_chain.hpp"
#include "ogive/limit/spreading.hpp"

namespace ogive::spreading_detail {

// Where a state's resultant leaves a wall: the ring's joint (a bed of the ring with the walls), which
// wall, the bed's height at d = 0 (m, y as the ring's), and whether the wall slides there (with
// friction: the resultant leaves the bed's friction cone) rather than tips (it leaves the bed; with a
// finite strength it comes within N / (2 f_c) of the bed's edge), or crushes (N > f_c b_w).
struct Tipping {
  int bed = -1;  // -1: the walls carry the state
  bool right = false;
  bool slides = false;
  bool crushes = false;
  bool stress_block = false;  // a finite strength: the resultant kept N / (2 f_c) inside the bed's faces
  double y = std::numeric_limits<double>::quiet_NaN();
  bool tips() const { return bed >= 0; }
};

// The checks of analyse_spreading on walls: no settlement share, a wall under each moving springing.
// Throws std::invalid_argument naming the field.
void check_spread_on_walls(const Scene& scene, const SpreadOptions& spread);

class SpreadWalls {
 public:
  // The walls of `ring` when it has some (else none).
  static std::optional<SpreadWalls> of(const Ring& ring, const SpreadOptions& spread);

  // `system`: the ring of the arch on its walls at d = 0 (Ring::left_wall_joints, right_wall_joints;
  // a wall on one side or on both). The wall of a side turns outwards by its share (SpreadOptions::
  // left_share, right_share) times d: the left one counter-clockwise about its base's outer toe, the
  // right one clockwise about its own; a side without a wall stays where it is.
  SpreadWalls(const Ring& system, const SpreadOptions& spread);

  // The arch's ring: the system's without the walls' beds and blocks (its joints the system's from the
  // left springing to the right one, the same coordinates).
  const Ring& arch() const { return arch_; }
  const SpringingMotion& left() const { return left_; }
  const SpringingMotion& right() const { return right_; }
  // The span's rate of increase at d = 0 (m per unit of d, > 0): the springings' intrados points'
  // horizontal velocities apart.
  double span_rate() const;

  // Whether the walls carry the state of the arch placed by `at` (its voussoirs' motions and the
  // springings', the walls': Placement) with the arch ring's reactions (H, V, M at the left springing,
  // as LimitLp::Answer) under live_factor times its live load: the resultant of the arch's reaction,
  // the blocks' weights and the top loads above each bed (where the walls have carried them) crosses
  // the bed between its faces in compression, to round-off (1e-9 of the bed), and (friction > 0) inside
  // its friction cone, |shear| <= friction * normal (to cone_excess' round-off). With a finite
  // compressive_strength f_c (Pa) the resultant must cross at least N / (2 f_c) inside each face (the
  // centre of the stress block N / f_c deep), so N <= f_c b_w (else the bed crushes). The lowest bed of
  // the left wall, then of the right one, that fails any (where a bed fails both, the wall tips).
  Tipping tipping(const Placement& at, double H, double V, double M, double live_factor, double friction,
                  double compressive_strength);

  // A wall's outward rotation (rad) at movement d and the outward horizontal displacement of its top's
  // outer corner (m); NaN for a side without a wall.
  double rotation(bool right, double d) const;
  double top_displacement(bool right, double d) const;

  // The system's hinges (on the ring with the walls) on the arch's ring: those in the walls left out.
  std::vector<Hinge> arch_hinges(std::vector<Hinge> hinges) const;
  // Into r at collapse (r.d_max, r.collapse set): each wall's lean, and with collapse wall_tips, or
  // sliding at a wall's bed (r.sliding_joint -1: no joint of the arch), which wall and bed (where `t`
  // says), the message, and for a slide the bed's axis point at collapse (r.sliding_point).
  void at_collapse(SpreadResult& r, const Tipping& t) const;
  // The path when the least-work state at d = 0 (`step`) already leaves a wall at `t` (the walls stand
  // under another state of the arch, not the one the movement starts from): that state, and the wall
  // tips (or slides) at once.
  SpreadResult tips_at_once(SpreadResult r, const SpreadStep& step, const Tipping& t) const;

 private:
  Ring system_, arch_, moved_;
  SpringingMotion left_, right_;
  Eigen::Vector2d left_top_, right_top_;  // the walls' tops' outer corners at d = 0
};

}  // namespace ogive::spreading_detail
