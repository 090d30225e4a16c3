// Adding a light to a scene file in place (tools/common/AddedLights.h): wherever the file
// keeps its lights, nodes and extension list (or keeps none yet), the light lands there,
// the bytes before the first insertion stay, and what cannot take a light is refused.
#include "AddedLights.h"

#include "engine/util/Error.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <string>

namespace {

tools::AddedLight pointLight(const std::string& name) {
    return {{{"name", name}, {"type", "point"}, {"intensity", 5}}, {{"name", name + "_node"}, {"translation", {1, 2, 3}}}};
}

// The file with one point light added, parsed; fails the test unless the light is the last of
// the list, placed by the last node, which is the last root of the displayed scene.
nlohmann::json addOne(const std::string& text) {
    const nlohmann::json out = nlohmann::json::parse(tools::addLights(text, {pointLight("added")}, "test.gltf"));
    const nlohmann::json& lights = out["extensions"]["KHR_lights_punctual"]["lights"];
    EXPECT_EQ(lights.back()["name"], "added");
    const nlohmann::json& node = out["nodes"].back();
    EXPECT_EQ(node["extensions"]["KHR_lights_punctual"]["light"], lights.size() - 1);
    EXPECT_EQ(out["scenes"][out.value("scene", 0)]["nodes"].back(), out["nodes"].size() - 1);
    const nlohmann::json& used = out["extensionsUsed"];
    EXPECT_EQ(std::count(used.begin(), used.end(), "KHR_lights_punctual"), 1) << used;
    return out;
}

TEST(AddedLights, GoWhereverTheFileKeepsItsLightsOrCreateThePlace) {
    // No extensions, no extensionsUsed, nodes present.
    const std::string bare = R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"name":"a"}]})";
    nlohmann::json out = addOne(bare);
    EXPECT_EQ(out["nodes"].size(), 2u);
    // The bytes before the first insertion are untouched.
    const std::string text = tools::addLights(bare, {pointLight("added")}, "test.gltf");
    EXPECT_EQ(text.substr(0, bare.find("]}]")), bare.substr(0, bare.find("]}]")));

    // Lights already there (index 1 for the new one), the extension already listed.
    out = addOne(R"({"asset":{"version":"2.0"},"scene":1,"scenes":[{"nodes":[]},{"nodes":[0]}],"nodes":[{}],
        "extensionsUsed":["KHR_lights_punctual"],"extensions":{"KHR_lights_punctual":{"lights":[{"type":"spot"}]}}})");
    EXPECT_EQ(out["nodes"][1]["extensions"]["KHR_lights_punctual"]["light"], 1);
    EXPECT_TRUE(out["scenes"][0]["nodes"].empty()) << "only the displayed scene gets the node";

    // Other extensions only, no nodes at all, a scene without a node list.
    out = addOne(R"({"asset":{"version":"2.0"},"scenes":[{}],"extensionsUsed":["KHR_x"],"extensions":{"KHR_x":{}}})");
    EXPECT_EQ(out["extensions"]["KHR_x"], nlohmann::json::object());
    EXPECT_EQ(out["extensionsUsed"], (nlohmann::json{"KHR_x", "KHR_lights_punctual"}));
    EXPECT_EQ(out["nodes"].size(), 1u);

    // The extension object without a light list.
    addOne(R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[]}],"nodes":[],"extensions":{"KHR_lights_punctual":{}}})");
}

TEST(AddedLights, AFileThatCannotTakeALightIsRefusedNamingIt) {
    for (const char* text : {R"({"asset":{"version":"2.0"}})",                                // no scene
                             R"({"asset":{"version":"2.0"},"scene":2,"scenes":[{}]})",        // no scene 2
                             R"({"asset":{"version":"2.0"},"scenes":[{}],"nodes":{}})",       // nodes not a list
                             R"({"asset":{"version":"2.0"},"scenes":[{}],"extensionsUsed":7})"}) {
        try {
            tools::addLights(text, {pointLight("added")}, "test.gltf");
            ADD_FAILURE() << "accepted " << text;
        } catch (const engine::InputError& error) {
            EXPECT_NE(std::string(error.what()).find("test.gltf"), std::string::npos) << error.what();
        }
    }
}

TEST(AddedLights, TheNodeIsTheSceneNodeAndTheLightItsLight) {
    engine::Scene scene;
    engine::Light light;
    light.name = "key";
    light.type = engine::Light::Type::Spot;
    light.intensity = 7.0f;
    light.innerConeAngle = 0.25;
    light.outerConeAngle = 0.5;
    scene.lights.push_back(light);
    engine::Node node;
    node.name = "key_node";
    node.light = 0;
    // Translated to (1, 2, 3) and turned a quarter about +Y.
    node.local = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(1, 2, 3)), glm::radians(90.0), glm::dvec3(0, 1, 0));
    scene.nodes.push_back(node);
    const tools::AddedLight added = tools::addedLightOf(scene, 0, {{"variant", "woo"}});
    EXPECT_EQ(added.light["type"], "spot");
    EXPECT_EQ(added.light["intensity"], 7.0);
    EXPECT_EQ(added.light["spot"]["outerConeAngle"], 0.5);
    EXPECT_EQ(added.light["extras"]["shadow"]["variant"], "woo");
    EXPECT_EQ(added.node["translation"], (nlohmann::json{1.0, 2.0, 3.0}));
    const double half = std::sqrt(0.5);  // (x, y, z, w) of a quarter turn about +Y
    const nlohmann::json& q = added.node["rotation"];
    EXPECT_NEAR(q[0].get<double>(), 0.0, 1e-15);
    EXPECT_NEAR(q[1].get<double>(), half, 1e-15);
    EXPECT_NEAR(q[2].get<double>(), 0.0, 1e-15);
    EXPECT_NEAR(q[3].get<double>(), half, 1e-15);
    EXPECT_FALSE(added.node.contains("scale"));
    EXPECT_FALSE(tools::addedLightOf(scene, 0, nlohmann::json::object()).light.contains("extras"));
}

} // namespace
