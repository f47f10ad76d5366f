#include "limit_text.hpp"

#include <fmt/format.h>

namespace ogive::cli {

const std::map<std::string, WeightModel>& weight_models() {
  static const std::map<std::string, WeightModel> names = {{"voussoir", WeightModel::voussoir},
                                                           {"axis", WeightModel::axis}};
  return names;
}

const std::map<std::string, JointOrientation>& joint_orientations() {
  static const std::map<std::string, JointOrientation> names = {{"radial", JointOrientation::radial},
                                                                {"vertical", JointOrientation::vertical}};
  return names;
}

std::string hinge_text(const std::vector<Hinge>& hinges, double span, const Ring* ring) {
  std::string text;
  for (const Hinge& h : hinges) {
    if (!text.empty()) text += ';';
    if (ring && (h.joint < ring->left_springing() || h.joint > ring->right_springing())) {
      text += fmt::format("{:.6g}:wall-{}@{:.6g}", h.point.x() / span, h.face == Face::extrados ? "outer" : "inner",
                          h.point.y() / span);
      continue;
    }
    text += fmt::format("{:.6g}:{}", h.point.x() / span, to_string(h.face));
  }
  return text;
}

}  // namespace ogive::cli
