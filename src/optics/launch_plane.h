// Where the optics analyses start their rays: in front of the first surface everywhere.
#pragma once

#include <algorithm>

#include "optics/prescription.h"

namespace eyetrace::optics {

// Most negative z the first surface reaches inside its clear aperture (50 mm when unlimited),
// minus a 1 mm margin, so a ray started there meets the first surface ahead of it.
inline double launch_plane(const Prescription& p) {
  const Surface& s = p.surfaces.front();
  const double h = std::min(s.limited() ? s.semi_diameter_mm : 50.0, s.profile.max_height());
  return std::min(0.0, s.profile.sag(h * h)) - 1.0;
}

}  // namespace eyetrace::optics
