// Scene files: defaults, every field, the bundled scenes, and every kind of bad input with the
// file, line and field it must name (expected lines are counted in the texts below, by hand).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "io/scene_json.hpp"

namespace nbscope {
namespace {

// The message parse_scene_json throws for `text`, or "" when it parses.
std::string error_of(const std::string& text) {
  try {
    parse_scene_json(text, "s.json");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(Scene, DefaultsOfAnEmptyScene) {
  const Scene s = parse_scene_json("{}", "dir/empty.json");
  EXPECT_EQ(s.name, "empty");
  EXPECT_EQ(s.gravity.x, 0);
  EXPECT_EQ(s.gravity.y, -10);
  EXPECT_DOUBLE_EQ(s.time_step, 1.0 / 60.0);
  EXPECT_EQ(s.sub_steps, 1);
  EXPECT_EQ(s.velocity_iterations, 8);
  EXPECT_EQ(s.position_iterations, 3);
  EXPECT_TRUE(s.continuous);
  EXPECT_FALSE(s.grid.cell_size);
  EXPECT_FALSE(s.grid.origin);
  EXPECT_FALSE(s.grid.cells);
  EXPECT_TRUE(s.bodies.empty());
  EXPECT_EQ(s.total_bodies(), 0);
}

TEST(Scene, EveryField) {
  const Scene s = parse_scene_json(R"({
    // comments are allowed
    "name": "all", "description": "text", "gravity": [1, -2], "time_step": 0.01, "sub_steps": 4,
    "velocity_iterations": 6, "position_iterations": 2, "continuous": false,
    "cell_size": 2.5, "origin": [-1, -2], "cells": [10, 12],
    "bodies": [
      {"type": "static", "shape": "box", "half_extents": [2, 0.5], "position": [3, 4], "angle": 0.5,
       "offset": [0.1, 0.2], "friction": 0.9},
      {"type": "kinematic", "shape": "circle", "radius": 0.25, "velocity": [1, 2], "angular_velocity": 3,
       "density": 2, "restitution": 0.5},
      {"shape": "polygon", "vertices": [[0, 0], [1, 0], [1, 1], [0, 1]]},
      {"position": [5, 5], "fixtures": [{"shape": "circle", "radius": 0.3, "offset": [-1, 0]},
                                         {"shape": "box", "half_extents": [0.5, 0.1], "angle": 1}]}
    ],
    "generators": [
      {"kind": "grid", "columns": 3, "rows": 2, "origin": [0, 0], "spacing": [1, 2]},
      {"kind": "random_box", "count": 10, "seed": 9, "min": [0, 0], "max": [5, 5], "radius": [0.1, 0.2],
       "speed": [1, 2], "random_angle": true, "body": {"shape": "circle"}},
      {"kind": "pile", "count": 7, "columns": 3, "position": [0, 1], "spacing": 1.5, "jitter": 0.1,
       "body": {"shape": "box", "half_extents": [0.2, 0.2]}},
      {"kind": "emitter", "count": 5, "position": [0, 9], "rate": 2, "start": 1, "width": 3, "spread": 0.5,
       "body": {"type": "dynamic", "shape": "circle", "radius": 0.2, "velocity": [0, -1]}}
    ]})",
                                   "all.json");
  EXPECT_EQ(s.name, "all");
  EXPECT_EQ(s.sub_steps, 4);
  EXPECT_FALSE(s.continuous);
  EXPECT_EQ(*s.grid.cell_size, 2.5);
  EXPECT_EQ((*s.grid.origin)[1], -2);
  EXPECT_EQ((*s.grid.cells)[1], 12);
  ASSERT_EQ(s.bodies.size(), 4u);
  EXPECT_EQ(s.bodies[0].type, BodyType::Static);
  EXPECT_EQ(s.bodies[0].fixtures[0].kind, ShapeKind::Box);
  EXPECT_EQ(s.bodies[0].fixtures[0].half_extents.x, 2);
  EXPECT_EQ(s.bodies[0].fixtures[0].offset.y, 0.2);
  EXPECT_EQ(s.bodies[0].angle, 0.5);
  EXPECT_EQ(s.bodies[0].fixtures[0].friction, 0.9);
  EXPECT_EQ(s.bodies[1].type, BodyType::Kinematic);
  EXPECT_EQ(s.bodies[1].fixtures[0].radius, 0.25);
  EXPECT_EQ(s.bodies[1].angular_velocity, 3);
  EXPECT_EQ(s.bodies[1].fixtures[0].restitution, 0.5);
  EXPECT_EQ(s.bodies[2].type, BodyType::Dynamic);
  EXPECT_EQ(s.bodies[2].fixtures[0].vertices.size(), 4u);
  ASSERT_EQ(s.bodies[3].fixtures.size(), 2u);
  EXPECT_EQ(s.bodies[3].fixtures[1].angle, 1);
  ASSERT_EQ(s.generators.size(), 4u);
  EXPECT_EQ(s.generators[0].count, 6);
  EXPECT_EQ(s.generators[1].seed, 9u);
  EXPECT_EQ((*s.generators[1].radius_range)[1], 0.2);
  EXPECT_TRUE(s.generators[1].random_angle);
  EXPECT_EQ(s.generators[2].spacing.x, 1.5);
  EXPECT_EQ(s.generators[3].rate, 2);
  EXPECT_EQ(s.generators[3].body.velocity.y, -1);
  EXPECT_EQ(s.total_bodies(), 4 + 6 + 10 + 7 + 5);
  // Messages about a body made later (e.g. by Box2D) can still name its file and line.
  EXPECT_EQ(s.bodies[2].fixtures[0].where, "all.json:11: bodies[2]: ");
}

TEST(Scene, EveryBundledSceneParses) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    const Scene s = read_scene_json(entry.path().string());
    EXPECT_GT(s.total_bodies(), 0);
    ++count;
  }
  EXPECT_GE(count, 7);
}

TEST(Scene, LargeSceneHasTwentyThousandBodies) {
  const Scene s = read_scene_json(std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/large.json");
  EXPECT_EQ(s.total_bodies(), 20'000);
}

struct BadScene {
  const char* name;
  const char* text;
  const char* message;  // the whole message after "s.json:"
};

class SceneBadInput : public ::testing::TestWithParam<BadScene> {};

TEST_P(SceneBadInput, NamesFileLineAndField) { EXPECT_EQ(error_of(GetParam().text), std::string("s.json:") + GetParam().message); }

const BadScene kBadScenes[] = {
    {"syntax_error", "{\n  \"gravity\": [0, -10],\n  \"bodies\": [\n    {\"shape\": \"circle\" \"radius\": 1}\n  ]\n}",
     "4: bodies[0]: JSON syntax error: syntax error while parsing object - unexpected string literal; expected '}'"},
    {"syntax_error_at_end", "{\"name\": \"x\",\n", "1: JSON syntax error: syntax error while parsing object key - unexpected end of input; expected string literal"},
    {"trailing_garbage", "{}\nx", "2: JSON syntax error: syntax error while parsing value - invalid literal; last read: 'x'; expected end of input"},
    {"empty_file", "", "1: JSON syntax error: syntax error while parsing value - unexpected end of input; expected '[', '{', or a literal"},
    {"nan_literal", "{\n\"bodies\": [{\"shape\": \"circle\",\n  \"radius\": NaN}]}",
     "3: bodies[0].radius: JSON syntax error: syntax error while parsing value - invalid literal; last read: 'N'"},
    {"infinite_number", "{\"bodies\": [\n{\"shape\": \"circle\", \"radius\": 1e999}]}",
     "2: bodies[0].radius: JSON syntax error: number out of range '1e999' (not a finite double)"},
    {"missing_radius", "{\"bodies\": [\n  {\"shape\": \"circle\",\n   \"position\": [0, 0]}\n]}",
     "2: bodies[0].radius: missing (a circle needs its radius)"},
    {"missing_shape", "{\"bodies\": [\n  {\"position\": [0, 0]}]}", "2: bodies[0].shape: missing (circle, box or polygon)"},
    {"missing_generator_count", "{\"generators\": [\n {\"kind\": \"random_box\", \"min\": [0, 0], \"max\": [1, 1]}]}",
     "2: generators[0].count: missing"},
    {"wrong_type_radius", "{\"bodies\": [{\"shape\": \"circle\",\n \"radius\": \"big\"}]}",
     "2: bodies[0].radius: must be a number, got a string \"big\""},
    {"null_radius", "{\"bodies\": [{\"shape\": \"circle\",\n \"radius\": null}]}", "2: bodies[0].radius: must be a number, got null"},
    {"null_bool", "{\"continuous\": null}", "1: continuous: must be true or false, got null"},
    {"wrong_type_gravity", "{\n\n\"gravity\": 10}", "3: gravity: must be an array of two numbers [a, b], got a number 10"},
    {"wrong_type_bool", "{\"continuous\": 1}", "1: continuous: must be true or false, got a number 1"},
    {"wrong_type_bodies", "{\"bodies\": {}}", "1: bodies: must be an array of bodies, got an object"},
    {"negative_radius", "{\"bodies\": [\n{\"shape\": \"circle\", \"radius\": 1},\n{\"shape\": \"circle\",\n \"radius\": -0.5}]}",
     "4: bodies[1].radius: must be positive, got -0.5"},
    {"negative_half_extent", "{\"bodies\": [{\"shape\": \"box\",\n \"half_extents\": [1, -1]}]}",
     "2: bodies[0].half_extents[1]: must be at least 0.005, got -1"},
    {"concave_polygon",
     "{\"bodies\": [{\"shape\": \"polygon\", \"vertices\": [\n  [0, 0],\n  [2, 0],\n  [1, 0.5],\n  [2, 2],\n  [0, 2]]}]}",
     "4: bodies[0].vertices[2]: polygon is not convex (concave at vertex 2)"},
    {"clockwise_polygon", "{\"bodies\": [{\"shape\": \"polygon\",\n \"vertices\": [[0, 0], [0, 1], [1, 0]]}]}",
     "2: bodies[0].vertices: polygon vertices are clockwise; list them counter-clockwise"},
    {"collinear_polygon", "{\"bodies\": [{\"shape\": \"polygon\", \"vertices\": [\n[0, 0],\n[1, 0],\n[2, 0],\n[1, 1]]}]}",
     "3: bodies[0].vertices[1]: degenerate polygon: vertices 0, 1, 2 are collinear"},
    {"repeated_vertex", "{\"bodies\": [{\"shape\": \"polygon\", \"vertices\": [\n[0, 0],\n[1, 0],\n[1, 0],\n[0, 1]]}]}",
     "4: bodies[0].vertices[2]: degenerate polygon: vertices 1 and 2 are 0 apart (at least 0.005)"},
    {"self_intersecting_polygon",
     "{\"bodies\": [{\"shape\": \"polygon\",\n \"vertices\": [[0, 1], [-0.588, -0.809], [0.951, 0.309], [-0.951, 0.309], [0.588, -0.809]]}]}",
     "2: bodies[0].vertices: polygon winds around 2 times (it crosses itself)"},
    {"too_many_vertices",
     "{\"bodies\": [{\"shape\": \"polygon\",\n \"vertices\": [[0,0],[1,0],[2,1],[2,2],[1,3],[0,3],[-1,2],[-1,1],[-0.5,0.2]]}]}",
     "2: bodies[0].vertices: a polygon has 3 to 8 vertices, got 9"},
    {"ten_million_bodies",
     "{\"bodies\": [{\"shape\": \"circle\", \"radius\": 1}],\n \"generators\": [\n  {\"kind\": \"random_box\",\n   \"count\": 10000000, \"min\": [0, 0], \"max\": [1, 1]}]}",
     "4: generators[0].count: 10000001 bodies requested in all; a scene holds at most 1000000"},
    {"grid_too_large", "{\"generators\": [{\"kind\": \"grid\", \"origin\": [0, 0],\n \"columns\": 5000,\n \"rows\": 5000}]}",
     "3: generators[0].rows: 25000000 bodies requested in all; a scene holds at most 1000000"},
    {"unknown_field", "{\"bodies\": [{\"shape\": \"circle\", \"radius\": 1,\n \"radus\": 2}]}",
     "2: bodies[0].radus: unknown field (known here: angle, angular_velocity, density, fixtures, friction, half_extents, "
     "offset, position, radius, restitution, shape, type, velocity, vertices)"},
    {"duplicate_key", "{\"gravity\": [0, 0],\n\"gravity\": [0, 1]}", "2: gravity: given twice (first on line 1)"},
    {"unknown_type", "{\"bodies\": [{\"type\": \"floating\",\n \"shape\": \"circle\", \"radius\": 1}]}",
     "1: bodies[0].type: must be \"dynamic\", \"static\" or \"kinematic\", got \"floating\""},
    {"unknown_generator", "{\"generators\": [{\n\"kind\": \"spiral\"}]}",
     "2: generators[0].kind: must be \"grid\", \"random_box\", \"pile\" or \"emitter\", got \"spiral\""},
    {"template_with_position", "{\"generators\": [{\"kind\": \"pile\", \"count\": 3, \"columns\": 1, \"position\": [0, 0],\n \"body\": {\"shape\": \"circle\",\n  \"position\": [1, 1]}}]}",
     "3: generators[0].body.position: the generator places its bodies; a template has no position"},
    {"negative_time_step", "{\"time_step\": -0.1}", "1: time_step: must be from 1e-6 to 1 second, got -0.1"},
    {"far_position", "{\"bodies\": [{\"shape\": \"circle\", \"radius\": 1, \"position\": [0,\n 1e9]}]}",
     "2: bodies[0].position[1]: must be within +-100000, got 1000000000"},
    {"not_an_object", "[1, 2]", "1: must be a scene (a JSON object), got an array [1,2]"},
    {"radius_on_box_template", "{\"generators\": [{\"kind\": \"random_box\", \"count\": 1, \"min\": [0, 0], \"max\": [1, 1],\n \"radius\": [0.1, 0.2],\n \"body\": {\"shape\": \"box\", \"half_extents\": [1, 1]}}]}",
     "2: generators[0].radius: radius applies to circle templates; use scale for other shapes"},
    {"grid_on_one_point", "{\"generators\": [{\"kind\": \"grid\", \"columns\": 1000, \"rows\": 1, \"origin\": [0, 0],\n \"spacing\": [0, 0]}]}",
     "2: generators[0].spacing: 0 along an axis with more than one body puts bodies on top of each other"},
    {"random_box_of_no_area", "{\"generators\": [{\"kind\": \"random_box\", \"count\": 50, \"min\": [1, 1],\n \"max\": [1, 1]}]}",
     "2: generators[0].max: equals min: all 50 bodies would be at one point"},
    {"scaled_beyond_shape_size", "{\"generators\": [{\"kind\": \"random_box\", \"count\": 5, \"min\": [0, 0], \"max\": [9, 9],\n"
     "  \"radius\": [1, 10000], \"scale\": [1, 10000]}]}",
     "2: generators[0].scale: scales a shape beyond 10000 m"},
    // Radii Box2D's float cannot hold (FLT_MIN is 1.18e-38; a dynamic circle's float mass
    // density * pi * r^2 must reach it too, or its inverse is infinite).
    {"radius_zero_in_float", "{\"bodies\": [{\"shape\": \"circle\",\n \"radius\": 1e-300}]}",
     "2: bodies[0].radius: 1e-300 m is 0 in Box2D's float: at least 1.18e-38 m"},
    {"radius_denormal_in_float", "{\"bodies\": [{\"type\": \"static\", \"shape\": \"circle\", \"radius\": 1e-40}]}",
     "1: bodies[0].radius: 1e-40 m is a denormal in Box2D's float: at least 1.18e-38 m"},
    {"radius_of_denormal_mass", "{\"bodies\": [{\"shape\": \"circle\",\n \"radius\": 1e-20, \"density\": 4}]}",
     "2: bodies[0].radius: 1e-20 m at density 4 makes a mass of 1.26e-39 kg in Box2D's float, whose inverse is infinite (its "
     "first step would turn the body NaN): at least 3.06e-20 m"},
    {"fixture_radius_of_denormal_mass", "{\"bodies\": [{\"fixtures\": [{\"shape\": \"circle\", \"radius\": 1},\n {\"shape\": \"circle\", \"radius\": 1e-21}]}]}",
     "2: bodies[0].fixtures[1].radius: 1e-21 m at density 1 makes a mass of 3.14e-42 kg in Box2D's float, whose inverse is infinite (its "
     "first step would turn the body NaN): at least 6.12e-20 m"},
    {"drawn_radius_of_denormal_mass", "{\"generators\": [{\"kind\": \"random_box\", \"count\": 5, \"min\": [0, 0], \"max\": [9, 9],\n"
     "  \"radius\": [1e-25, 1]}]}",
     "2: generators[0].radius[0]: 1e-25 m at density 1 makes a mass of 0 kg in Box2D's float, whose inverse is infinite (its "
     "first step would turn the body NaN): at least 6.12e-20 m"},
};

INSTANTIATE_TEST_SUITE_P(All, SceneBadInput, ::testing::ValuesIn(kBadScenes),
                         [](const ::testing::TestParamInfo<BadScene>& info) { return std::string(info.param.name); });

// A static body has no mass in Box2D: only its radius must be a float.
TEST(Scene, AStaticCircleTooLightToBeDynamicIsRead) {
  const Scene s = parse_scene_json("{\"bodies\": [{\"type\": \"static\", \"shape\": \"circle\", \"radius\": 1e-20}]}", "s.json");
  EXPECT_EQ(s.bodies[0].fixtures[0].radius, 1e-20);
}

TEST(Scene, UnreadableFile) {
  try {
    read_scene_json("/nonexistent/scene.json");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/scene.json: cannot open the scene file (no such file or not readable)");
  }
}

}  // namespace
}  // namespace nbscope
