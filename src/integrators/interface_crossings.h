// The bound on medium-interface crossings along one path segment of the volume-aware integrators.
#pragma once

namespace eyetrace {

// Interface crossings do not count as bounces; bound them so a degenerate scene cannot loop.
inline constexpr int kMaxInterfaceCrossings = 256;

}  // namespace eyetrace
