// SceneData queries on small hand-made scenes (no file I/O).

#include "scene/SceneData.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

namespace {

using cube::SceneData;
using cube::SceneNode;

SceneNode boxNode(const std::string& name, glm::vec3 lo, glm::vec3 hi, int parent = -1) {
    SceneNode n;
    n.name = name;
    n.parent = parent;
    n.meshes = {0};
    n.aabbMin = lo;
    n.aabbMax = hi;
    return n;
}

SceneData groundScene() {
    SceneData s;
    SceneNode grass = boxNode("grass", {-10, 0, -10}, {10, 0, 10});
    grass.surface = "grass";
    SceneNode road = boxNode("road", {-10, 0, -2}, {10, 0.02f, 2});
    road.surface = "asphalt";
    SceneNode sand = boxNode("sand", {5, 0, -5}, {8, 0.01f, 5});
    sand.surface = "sand";
    SceneNode untagged = boxNode("roof", {-1, 3, -1}, {1, 3.5f, 1});  // no surface: never ground
    SceneNode noMesh = boxNode("marker", {-10, 5, -10}, {10, 5, 10});
    noMesh.surface = "gravel";
    noMesh.meshes.clear();  // a node without meshes takes part in no query
    s.nodes = {grass, road, sand, untagged, noMesh};
    return s;
}

TEST(SceneData, SurfaceAtPicksTheHighestGroundNodeInclusiveOfEdges) {
    const SceneData s = groundScene();
    EXPECT_EQ(s.surfaceAt(0, 0), "asphalt");
    EXPECT_EQ(s.surfaceAt(0, 2), "asphalt");  // edge belongs to the higher node
    EXPECT_EQ(s.surfaceAt(0, 2.01f), "grass");
    EXPECT_EQ(s.surfaceAt(6, 4), "sand");     // sand (0.01) above grass (0)
    EXPECT_EQ(s.surfaceAt(6, 0), "asphalt");  // road (0.02) above sand (0.01)
    EXPECT_EQ(s.surfaceAt(10, 10), "grass");
    EXPECT_EQ(s.surfaceAt(10.01f, 0), "");
}

TEST(SceneData, FindNodePrefixAndDescendants) {
    SceneData s;
    s.nodes = {boxNode("car", {}, {}), boxNode("wheel_FL", {}, {}, 0), boxNode("hub", {}, {}, 1),
               boxNode("wheelbarrow", {}, {})};
    EXPECT_EQ(s.findNode("wheel_FL"), 1);
    EXPECT_EQ(s.findNode("wheel"), -1);
    EXPECT_EQ(s.nodesWithPrefix("wheel"), (std::vector<int>{1, 3}));
    EXPECT_TRUE(s.nodesWithPrefix("tyres").empty());
    EXPECT_TRUE(s.isDescendant(2, 0));
    EXPECT_TRUE(s.isDescendant(1, 0));
    EXPECT_FALSE(s.isDescendant(0, 0));
    EXPECT_FALSE(s.isDescendant(0, 2));
    EXPECT_FALSE(s.isDescendant(3, 0));
    EXPECT_FALSE(s.isDescendant(-1, 0));
    EXPECT_FALSE(s.isDescendant(2, 99));
}

TEST(SceneData, PenetrationDepthAgainstSolidBoxes) {
    SceneData s;
    SceneNode wall = boxNode("barrier", {0, 0, 0}, {10, 1, 1});
    wall.solid = true;
    SceneNode decoration = boxNode("flag", {-5, 0, -5}, {5, 1, 5});  // not solid: ignored
    s.nodes = {wall, decoration};

    int hit = 7;
    EXPECT_EQ(s.penetrationDepth({5, 0.5f, 3}, 1.0f, &hit), 0.0f);  // 2 m away
    EXPECT_EQ(hit, -1);
    EXPECT_EQ(s.penetrationDepth({5, 0.5f, 2}, 1.0f, &hit), 0.0f);  // exactly touching
    EXPECT_NEAR(s.penetrationDepth({5, 0.5f, 1.25f}, 1.0f, &hit), 0.75f, 1e-6f);
    EXPECT_EQ(hit, 0);
    // Corner: closest point (10,1,1), distance sqrt(0.5^2 * 2) = 0.7071.
    EXPECT_NEAR(s.penetrationDepth({10.5f, 1.5f, 1.0f}, 1.0f, &hit), 1.0f - 0.70710678f, 1e-5f);
    // Centre inside: nearest face is z = 1 (0.2 away), so depth = radius + 0.2.
    EXPECT_NEAR(s.penetrationDepth({5, 0.5f, 0.8f}, 0.5f, &hit), 0.7f, 1e-6f);
    EXPECT_EQ(hit, 0);
}

TEST(SceneData, SolidsOverlappingABox) {
    SceneData s;
    SceneNode a = boxNode("tyres_0", {0, 0, 0}, {1, 1, 1});
    a.solid = true;
    SceneNode b = boxNode("tyres_1", {5, 0, 0}, {6, 1, 1});
    b.solid = true;
    s.nodes = {a, b, boxNode("grass", {-9, 0, -9}, {9, 0, 9})};
    EXPECT_EQ(s.solidsOverlapping({0.5f, 0.5f, 0.5f}, {5.5f, 0.6f, 0.6f}),
              (std::vector<int>{0, 1}));
    EXPECT_EQ(s.solidsOverlapping({1, 0, 0}, {2, 1, 1}), (std::vector<int>{0}));  // touching counts
    EXPECT_TRUE(s.solidsOverlapping({2, 0, 0}, {4, 1, 1}).empty());
}

}  // namespace

// The wheels turn through setLocal: the node and its subtree move, its siblings and parent do not.
TEST(SceneData, SetLocalMovesTheNodeAndItsSubtreeOnly) {
    SceneData s;
    s.nodes = {boxNode("car", {}, {}), boxNode("wheel_FL", {}, {}, 0), boxNode("hub", {}, {}, 1),
               boxNode("wheel_FR", {}, {}, 0)};
    s.nodes[0].local = s.nodes[0].world = glm::translate(glm::mat4(1.0f), {10.0f, 0.0f, 0.0f});
    s.nodes[1].local = glm::translate(glm::mat4(1.0f), {1.35f, 0.33f, -0.8f});
    s.nodes[2].local = glm::translate(glm::mat4(1.0f), {0.0f, 0.2f, 0.0f});  // 0.2 m up from the axle
    s.nodes[3].local = glm::translate(glm::mat4(1.0f), {1.35f, 0.33f, 0.8f});
    for (size_t i = 1; i < s.nodes.size(); ++i)
        s.nodes[i].world = s.nodes[size_t(s.nodes[i].parent)].world * s.nodes[i].local;
    const glm::mat4 carBefore = s.nodes[0].world, frBefore = s.nodes[3].world;

    // A quarter turn about the axle (+Z), rolling forward: the point above the axle goes to +X.
    s.setLocal(1, glm::rotate(s.nodes[1].local, -0.5f * 3.14159265f, glm::vec3(0, 0, 1)));
    const glm::vec3 hub = glm::vec3(s.nodes[2].world[3]);
    EXPECT_NEAR(hub.x, 10.0f + 1.35f + 0.2f, 1e-5f);
    EXPECT_NEAR(hub.y, 0.33f, 1e-5f);
    EXPECT_NEAR(hub.z, -0.8f, 1e-5f);
    EXPECT_NEAR(s.nodes[1].world[3].x, 11.35f, 1e-5f);  // the axle stays
    EXPECT_EQ(s.nodes[0].world, carBefore);
    EXPECT_EQ(s.nodes[3].world, frBefore);
    s.setLocal(7, glm::mat4(2.0f));  // out of range: nothing
    s.setLocal(-1, glm::mat4(2.0f));
    EXPECT_EQ(s.nodes[3].world, frBefore);
}
