// The scenes of a sweep, one at a time: the product of the scene options' values, never held all at
// once (a million scenes must not cost memory). Malformed options (a value outside its rule, an unknown
// curve) are refused when the plan is made, before anything is printed; a combination of valid values
// that makes no scene (a thickness that does not fit a flat arch) is a row of its own, status
// invalid_scene.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ogive/geometry/curve.hpp"
#include "ogive/model/scene.hpp"
#include "scene_options.hpp"

namespace ogive::cli {

class ScenePlan {
 public:
  // Reads the curve's points and the loads file into `o`; UsageError for malformed options, or when
  // no scene of the sweep can be made (the first one's reason).
  ScenePlan(SceneOptions& o, const CLI::App& cmd);

  std::size_t size() const { return size_; }
  bool no_tension() const { return section_ == SectionKind::no_tension; }
  // --beam-model auto or --model-tolerance: each row's model is judged (the beam_model and
  // model_error_estimate columns are printed by default).
  bool asks_model_error() const { return beam_model_ == BeamModel::automatic || model_tolerance_ > 0; }

  // The columns of the inputs that take more than one value.
  std::vector<std::string> varying_inputs() const;

  // Scene number `index` (0-based) of the sweep; the last axis varies fastest.
  SceneParameters parameters(std::size_t index) const;

  // The scene of p, or why there is none (one line naming the option and the rule): the curve's
  // factory and Scene::validate judge the combination.
  struct Built {
    std::optional<Scene> scene;
    std::shared_ptr<const Curve> curve;  // set whenever the curve itself could be made
    std::string problem;
  };
  Built build(const SceneParameters& p) const;

  // A message of the library about a scene (std::invalid_argument's), in the options' words as the user
  // gave them: "thickness: ..." names --thickness or --thickness-ratio, whichever was given.
  std::string problem_words(const std::string& what) const;

 private:
  void choose_supports(const SceneOptions& o, const CLI::App& cmd);
  void plan_axes(SceneOptions& o, const CLI::App& cmd);
  void require_some_scene() const;
  void warn_of_small_loads(const SceneParameters& p, const Scene& scene) const;
  void lean_walls(const SceneParameters& p, Scene& scene) const;
  std::shared_ptr<const Curve> make_curve(const SceneParameters& p) const;
  void derive_metres(SceneParameters& p) const;
  void choose_dimensions(const SceneOptions& o, const CLI::App& cmd);
  void to_axis_dimensions(SceneParameters& p) const;
  void check_metres(const SceneParameters& p) const;

  const SceneOptions& options_;
  const CurveFamily* family_ = nullptr;
  SupportKind left_kind_ = SupportKind::clamped, right_kind_ = SupportKind::clamped;
  SectionKind section_ = SectionKind::elastic;
  BeamModel beam_model_ = BeamModel::timoshenko;
  double model_tolerance_ = 0;
  std::size_t size_ = 1;
  std::string thickness_flag_;   // --thickness-ratio or --thickness: the one the user's thickness came by
  std::string spread_flags_[2];  // each springing's spread came by: --left-spread-ratio (--right-...) or
                                 // --support-displacement-ratio
  // The side's wall options (--left-wall-height, ...) whose value came by the shared one (--wall-height).
  std::vector<std::string> walls_by_shared_flag_;
  std::string shape_flag_;       // what set the pointed arch's shape: --eccentricity, --rise-ratio, --rise, --radius
  std::string live_from_flag_, live_to_flag_;  // the live load's ends: --live-load-from or --live-load-from-x, ...
  bool fill_to_crown_ = false;   // --fill-height crown or crown+D
  double fill_over_crown_ = 0;   // m, D of crown+D (crown-D: below it)
  bool intrados_ = false;        // --dimensions intrados: --span and --rise are the intrados' (NaN rise:
                                 // the semicircle's)
  // --point-load and --live-load given as bare numbers in N (neither a unit nor --units kN): build()
  // warns where one is too small to have been meant in N.
  bool bare_newton_point_ = false, bare_newton_live_ = false;
  bool fill_in_metres_ = false;  // --fill-height given
  double force_unit_ = 1.0;      // N per unit of the force options (--units)
};

}  // namespace ogive::cli
