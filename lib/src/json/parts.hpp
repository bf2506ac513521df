#pragma once
// Readers of each part of a scene file (docs/scene.md), on the JSON
// toolkit of reader.hpp. Each reads its key from `top` into the scene and
// checks what it can alone; checks across parts and observations are the
// scene reader's (scene_json.cpp).

#include <string>

#include "pendulum/parsed_scene.hpp"
#include "reader.hpp"

namespace pendulum::json_reader {

inline constexpr double kMaxDensity = 22590.0;       // osmium (kg/m^3)
inline constexpr double kMaxYoungsModulus = 1.2e12;  // diamond (Pa)

/// timing: trials -> the observation's mean period and its uncertainty
/// (Nelson & Olsson Eq. 4); warnings about trials that disagree.
void read_timing(Object& parent, const std::string& prefix, Observation<double>& value, Observation<double>& sigma,
                 ObservationSource& source, ParsedScene& out);

/// bob, ring, cap, cap_screw, wire, air, support: the apparatus's parts.
void read_parts(Object& top, ParsedScene& out);

class RecordingReader;

/// decay: alpha and beta as measured, and/or a record to fit them from
/// (numbers, or a recording that `recordings` reads).
void read_decay(Object& top, ParsedScene& out, RecordingReader& recordings);

/// site: a measured reference g, or latitude and height for normal gravity.
void read_site(Object& top, ParsedScene& out);

}  // namespace pendulum::json_reader
