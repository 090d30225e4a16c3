// Nodes and the assembly of the engine scene.
#include "GltfConvert.h"

#include "GltfAnimations.h"
#include "GltfImages.h"
#include "GltfLights.h"
#include "GltfMeshes.h"
#include "GltfSkins.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cctype>
#include <vector>

namespace engine::gltf {

namespace {

// The node's TRS (identity parts where absent) and M relative to its parent: the matrix
// (column-major, as glTF stores it), or T * R * S. Lengths, finiteness and a non-zero
// quaternion were checked by validation.
void readLocalTransform(const tinygltf::Node& source, Node& node) {
    if (source.translation.size() == 3) node.translation = glm::make_vec3(source.translation.data());
    if (source.rotation.size() == 4) {
        // glTF stores (x, y, z, w); glm's constructor takes w first. Exporters write
        // quaternions rounded to float: normalize so no scale sneaks in.
        const glm::dquat q(source.rotation[3], source.rotation[0], source.rotation[1], source.rotation[2]);
        node.rotation = glm::normalize(q);
    }
    if (source.scale.size() == 3) node.scale = glm::make_vec3(source.scale.data());
    node.local = source.matrix.size() == 16 ? glm::make_mat4(source.matrix.data()) : node.trsMatrix();
}

// Lower case without '_', '-' or spaces: "Cast-Shadows" and "castShadows" read alike.
std::string foldKey(const std::string& key) {
    std::string folded;
    for (const char c : key)
        if (c != '_' && c != '-' && c != ' ') folded += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return folded;
}

// Levenshtein distance (insertions, deletions, substitutions), one row at a time.
std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

// Node extras "cast_shadows" / "receive_shadows": booleans, or the integers 0 and 1 as
// Blender writes a boolean custom property; any other value is an error. Default true. Node extras are shared with every exporter (Blender's custom properties,
// three.js userData), so other keys are not ours to refuse; but a key that reads like one
// of ours (a typo such as "cast_shadow", or "castShadows") is almost surely meant as ours,
// and ignoring it would silently shadow what the author opted out: a warning names the
// node, the key and the one we read.
void readShadowFlags(const LoadContext& context, const tinygltf::Node& source, const std::string& object, Node& node) {
    if (!source.extras.IsObject()) return;
    static constexpr const char* kOurs[] = {"cast_shadows", "receive_shadows"};
    const auto flag = [&](const char* key, bool& target) {
        if (!source.extras.Has(key)) return;
        const tinygltf::Value& value = source.extras.Get(key);
        if (value.IsBool()) {
            target = value.Get<bool>();
            return;
        }
        const double number = value.IsNumber() ? value.GetNumberAsDouble() : -1.0;
        if (number != 0.0 && number != 1.0)
            context.fail(object, std::string("extras.") + key + " is not a boolean (true, false, or Blender's 1 or 0)");
        target = number == 1.0;
    };
    flag(kOurs[0], node.castShadows);
    flag(kOurs[1], node.receiveShadows);
    for (const std::string& key : source.extras.Keys()) {
        if (key == kOurs[0] || key == kOurs[1]) continue;
        for (const char* ours : kOurs)
            // Two edits on the folded key: a dropped or doubled letter, a swapped pair.
            if (editDistance(foldKey(key), foldKey(ours)) <= 2)
                context.warn(object, "extras." + key + " is not read (did you mean \"" + ours + "\"?)");
    }
}

std::vector<Node> convertNodes(const LoadContext& context, const tinygltf::Model& model) {
    std::vector<Node> nodes(model.nodes.size());
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        const tinygltf::Node& source = model.nodes[i];
        const std::string object = indexedNamed("nodes", i, source.name);
        Node& node = nodes[i];
        node.name = source.name;
        node.children = source.children;
        readLocalTransform(source, node);
        node.mesh = source.mesh;
        node.camera = source.camera;
        node.light = nodeLightIndex(context, source, i);
        readShadowFlags(context, source, object, node);
    }
    for (std::size_t i = 0; i < nodes.size(); ++i)
        for (int child : nodes[i].children) nodes[child].parent = static_cast<int>(i);
    return nodes;
}

// The nodes of the scene to display: the default scene, else scene 0; a file without
// scenes shows every root node (the glTF spec leaves that case to the application).
std::vector<int> displayedRoots(const LoadContext& context, const tinygltf::Model& model, const std::vector<Node>& nodes) {
    if (!model.scenes.empty()) return model.scenes[model.defaultScene >= 0 ? model.defaultScene : 0].nodes;
    std::vector<int> roots;
    for (std::size_t i = 0; i < nodes.size(); ++i)
        if (nodes[i].parent == -1) roots.push_back(static_cast<int>(i));
    if (!roots.empty()) context.warn("scenes", "none defined; showing every root node");
    return roots;
}

} // namespace

Scene convertToScene(const LoadContext& context, const ParsedGltf& parsed, const nlohmann::json& document,
                     std::vector<Light> lights) {
    const tinygltf::Model& model = parsed.model;
    Scene scene;
    scene.sourcePath = context.file;
    scene.nodes = convertNodes(context, model);
    scene.roots = displayedRoots(context, model, scene.nodes);
    // Materials first: a primitive's warning about a missing UV set names its material's.
    scene.materials = convertMaterials(context, model, document);
    scene.meshes = convertMeshes(context, model, document, scene.materials);
    scene.skins = readSkins(context, model);
    attachDeformers(context, model, scene.skins, scene.meshes, scene.nodes);
    scene.images = decodeImages(context, parsed);
    scene.cameras = convertCameras(context, model);
    scene.lights = std::move(lights);
    scene.animations = readAnimations(context, model, document);
    scene.updateWorldTransforms();
    return scene;
}

} // namespace engine::gltf
