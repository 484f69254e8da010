// The world's checks (physics/world_checks.cpp): what Box2D's float makes of a body
// (box2d_float_trouble, physics/fixture_shape.hpp), each case's mass and inertia worked by hand, and
// the world that refuses such a body before making any.
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "core/error.hpp"
#include "physics/fixture_shape.hpp"
#include "physics/world.hpp"
#include "support/physics_context.hpp"

namespace nbscope {
namespace {

using testphysics::circle_body;

// A circle radius that is 0 or a denormal in float is named with its value.
TEST(Box2dFloats, ARadiusThatIsZeroInFloatIsNamed) {
  EXPECT_EQ(box2d_float_trouble(circle_body(0.5)), "");
  const std::string t = box2d_float_trouble(circle_body(1e-300, BodyType::Static));
  EXPECT_NE(t.find("radius 1e-300 m is 0 in Box2D's float"), std::string::npos) << t;
  EXPECT_NE(box2d_float_trouble(circle_body(1e-40, BodyType::Static)).find("is a denormal"), std::string::npos);
}

// A dynamic body whose float mass is a denormal is named; static bodies and normal masses are not.
TEST(Box2dFloats, ADynamicBodyWhoseFloatMassIsADenormalIsNamed) {
  // pi * (1e-20)^2 = 3.1e-40 kg: below FLT_MIN (1.2e-38), its inverse infinite.
  const std::string t = box2d_float_trouble(circle_body(1e-20));
  EXPECT_NE(t.find("its mass in Box2D's float is a denormal"), std::string::npos) << t;
  EXPECT_EQ(box2d_float_trouble(circle_body(1e-20, BodyType::Static)), "");  // Box2D gives static bodies no mass
  EXPECT_EQ(box2d_float_trouble(circle_body(1e-19)), "");                      // 3.1e-38 kg: a normal float
  BodySpec light = circle_body(1);
  light.fixtures[0].density = 1e-40;
  EXPECT_NE(box2d_float_trouble(light).find("density 1e-40"), std::string::npos);
  light.fixtures[0].density = 0;  // no density: Box2D makes it 1 kg
  EXPECT_EQ(box2d_float_trouble(light), "");
}

// An inertia about the centre of mass that rounds to 0 in float is named (dynamic bodies only).
TEST(Box2dFloats, AnInertiaThatRoundsAwayIsNamed) {
  // I = m (r^2 / 2 + 1) - m * 1: r^2 / 2 = 5e-9 is below float's step at 1, so I rounds to 0 and
  // b2Body::ResetMassData's assertion would abort.
  const std::string t = box2d_float_trouble(circle_body(1e-4, BodyType::Dynamic, {1, 0}));
  EXPECT_NE(t.find("rotational inertia"), std::string::npos) << t;
  EXPECT_EQ(box2d_float_trouble(circle_body(1e-2, BodyType::Dynamic, {1, 0})), "");
  EXPECT_EQ(box2d_float_trouble(circle_body(1e-4, BodyType::Kinematic, {1, 0})), "");
}

// Building a world with such a body (generated or poured) throws naming the generator's body.
TEST(Box2dFloats, TheWorldRefusesSuchABodyNamingItBeforeMakingAny) {
  Scene scene;
  scene.path = "tiny.json";
  GeneratorSpec g;
  g.kind = GeneratorKind::RandomBox;
  g.count = 10;
  g.max = {10, 10};
  g.radius_range = std::array<double, 2>{1e-40, 1e-39};
  g.body = circle_body(0.5);
  g.body.where = "tiny.json:3: generators[0].body: ";
  scene.bodies.push_back(circle_body(0.5));
  scene.generators.push_back(g);
  try {
    PhysicsWorld world(scene);
    FAIL() << "built";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("tiny.json:3: generators[0].body: body #0: radius ", 0), 0u) << e.what();
  }
  // An emitter's bodies are the same every time: its template is checked when the world is built.
  scene.generators[0].kind = GeneratorKind::Emitter;
  scene.generators[0].body.fixtures[0].radius = 1e-40;
  try {
    PhysicsWorld world(scene);
    FAIL() << "built";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("tiny.json:3: generators[0].body: every body it pours: ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace nbscope
