// nbscope io (internal): the bodies of scene files (io/scene_json.hpp's format) and their shapes,
// read and validated; and what generators need to know of a template body's shapes.
#pragma once
#include "io/scene_json_fields.hpp"
#include "physics/scene.hpp"

namespace nbscope::scene_fields {

// A body, or with `is_template` a generator's body (no position: the generator sets it).
BodySpec read_body(const LocatedJson& doc, const json& v, const Path& path, bool is_template);
// Fails (at `path`) on a circle radius Box2D's float does not hold, or whose mass at a positive
// `density` (a dynamic body's) would be 0 or a denormal there.
void check_radius_in_float(const LocatedJson& doc, const Path& path, double radius, double density);
// The smallest box half extent or polygon edge of `b` (1e300 without either): what scale may not shrink below Box2D's weld distance.
double smallest_feature(const BodySpec& b);
// The largest size, offset or vertex distance of `b`'s shapes: what scale may not grow beyond kMaxShapeSize.
double largest_feature(const BodySpec& b);

}  // namespace nbscope::scene_fields
