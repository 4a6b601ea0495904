// The worlds target brings Box2D, toml++ and assimp: each is called once here.
#include <assimp/Importer.hpp>
#include <toml++/toml.h>

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include <string_view>

namespace {

// Records the closest hit of a Box2D ray cast.
struct ClosestHit : b2RayCastCallback {
  float fraction = 1.0f;
  float ReportFixture(b2Fixture*, const b2Vec2&, const b2Vec2&, float f) override {
    fraction = f;
    return f;  // clip the ray to this hit, so the closest one wins
  }
};

TEST(WorldsDependencies, Box2DRayCastHitsAWall) {
  b2World world(b2Vec2(0.0f, 0.0f));
  b2BodyDef def;
  b2Body* wall = world.CreateBody(&def);
  b2PolygonShape box;
  box.SetAsBox(0.5f, 5.0f, b2Vec2(3.0f, 0.0f), 0.0f);  // a wall whose near face is at x = 2.5
  wall->CreateFixture(&box, 0.0f);
  ClosestHit hit;
  world.RayCast(&hit, b2Vec2(0.0f, 0.0f), b2Vec2(10.0f, 0.0f));
  EXPECT_NEAR(hit.fraction * 10.0f, 2.5f, 1e-5f);
}

TEST(WorldsDependencies, TomlParsesAWorld) {
  constexpr std::string_view text = R"(
    name = "room"
    [[wall]]
    from = [0.0, 0.0]
    to = [4.0, 0.0]
  )";
  toml::table t = toml::parse(text);
  EXPECT_EQ(t["name"].value_or(""), std::string("room"));
  EXPECT_DOUBLE_EQ(t["wall"][0]["to"][0].value_or(0.0), 4.0);
  EXPECT_EQ(t["wall"][0]["to"].node()->source().begin.line, 5u);
}

TEST(WorldsDependencies, AssimpLoadsAnObjFromMemory) {
  constexpr std::string_view obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n";
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFileFromMemory(obj.data(), obj.size(), aiProcess_Triangulate, "obj");
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  ASSERT_EQ(scene->mNumMeshes, 1u);
  EXPECT_EQ(scene->mMeshes[0]->mNumFaces, 2u);
}

}  // namespace
