#include "pendulum/parsed_scene.hpp"

namespace pendulum {

bool ObservationSource::is_shared(const std::string& key) const {
  const std::string head = key.substr(0, key.find('.'));
  for (const auto& s : shared) {
    if (s == head) return true;
  }
  return false;
}

std::string ObservationSource::path_of(const std::string& key) const { return is_shared(key) ? key : path + key; }

AngleOf decay_angle_of(const ParsedScene& scene) {
  return scene.decay_data ? scene.decay_data->angle_of : AngleOf::pendulum;
}

}  // namespace pendulum
