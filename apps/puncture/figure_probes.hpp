#pragma once
// `puncture figures`' probe comparison (figure "probes"): the flat punch, sharp and with a rounded
// corner, the sphere-tipped probe and a cone with a spherical tip, all of one radius, on the
// flags' membrane without friction.
#include <nlohmann/json.hpp>

#include "puncture/problem.hpp"

namespace puncture::cli {

// Each probe's outline (r, z above its tip [mm]), loading curve (`points` depths) and puncture
// point with its energy [mJ]; a probe whose model ends before puncture has no curve and says why
// ("failure").
nlohmann::ordered_json probes_figure(const Problem& base, int points);

}  // namespace puncture::cli
