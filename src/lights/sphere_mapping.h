// The two ways an environment image lays the sphere of directions on the unit square
// (u across, v down the rows, (0,0) the top-left pixel corner), in the light's own frame.
//
// Equal-area octahedral (pbrt-v4's format; Clarberg, "Fast Equal-Area Mapping of the
// (Hemi)Sphere using SIMD", 2008): square images. The image centre looks along +z and the
// four corners along -z; the inner diamond |2u-1| + |2v-1| < 1 is the upper hemisphere, its
// edge the horizon, whose points at the middles of the right/left/bottom/top image edges
// look along +x/-x/+y/-y. Every pixel covers the same solid angle, 4 pi / (width * height).
//
// Latitude-longitude (the equirectangular format of pbrt-v3, 2:1 images):
// u = phi / (2 pi) with phi = atan2(y, x) in [0, 2 pi), v = theta / pi with theta = acos(z),
// so the top row looks along +z and the middle row is the horizon z = 0. A pixel at polar
// angle theta covers (2 pi / width) (pi / height) sin(theta) steradians.
#pragma once
#include "core/math.h"

namespace eyetrace {

Vec3 equal_area_square_to_sphere(Vec2 p);
Vec2 equal_area_sphere_to_square(const Vec3& d);  // d unit

Vec3 latlong_square_to_sphere(Vec2 p);
Vec2 latlong_sphere_to_square(const Vec3& d);  // d unit

}  // namespace eyetrace
