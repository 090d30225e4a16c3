// The node hierarchy must be a forest and every transform well formed: tinygltf 2.7.0
// checks neither, and a cycle would hang (or overflow) any traversal.
#include "GltfValidation.h"

#include <cmath>
#include <set>

namespace engine::gltf {

namespace {

std::string nodeName(const tinygltf::Model& model, std::size_t index) {
    return indexedNamed("nodes", index, model.nodes[index].name);
}

bool allFinite(const std::vector<double>& values) {
    for (double v : values)
        if (!std::isfinite(v)) return false;
    return true;
}

void checkTransform(const LoadContext& context, const tinygltf::Model& model, std::size_t index) {
    const tinygltf::Node& node = model.nodes[index];
    const std::string object = nodeName(model, index);
    const auto checkVector = [&](const char* what, const std::vector<double>& values, std::size_t length) {
        if (!values.empty() && values.size() != length)
            context.fail(object, std::string(what) + " has " + std::to_string(values.size()) + " numbers, not " +
                                     std::to_string(length));
        if (!allFinite(values)) context.fail(object, std::string(what) + " holds a number that is not finite");
    };
    checkVector("matrix", node.matrix, 16);
    checkVector("translation", node.translation, 3);
    checkVector("rotation", node.rotation, 4);
    checkVector("scale", node.scale, 3);
    if (!node.rotation.empty()) {
        const double lengthSquared = node.rotation[0] * node.rotation[0] + node.rotation[1] * node.rotation[1] +
                                     node.rotation[2] * node.rotation[2] + node.rotation[3] * node.rotation[3];
        if (!(lengthSquared > 0.0) || !std::isfinite(lengthSquared))
            context.fail(object, "rotation is a zero quaternion");
    }
}

// parent[i] is the node listing i as a child, -1 for none; two parents are refused.
std::vector<int> assignParents(const LoadContext& context, const tinygltf::Model& model) {
    std::vector<int> parent(model.nodes.size(), -1);
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        for (int child : model.nodes[i].children) {
            if (static_cast<std::size_t>(child) == i) context.fail(nodeName(model, i), "lists itself as a child");
            if (parent[child] != -1)
                context.fail(nodeName(model, child), "has two parents: " + nodeName(model, parent[child]) + " and " +
                                                         nodeName(model, i));
            parent[child] = static_cast<int>(i);
        }
    }
    return parent;
}

// With one parent per node, a node lies on or below a cycle exactly when it cannot be
// reached from a parentless node. Walking up from such a node must repeat a node, and the
// first repeated one is on the cycle: that is the one the message names.
void refuseCycles(const LoadContext& context, const tinygltf::Model& model, const std::vector<int>& parent) {
    std::vector<bool> reached(model.nodes.size(), false);
    std::vector<int> stack;
    for (std::size_t i = 0; i < model.nodes.size(); ++i)
        if (parent[i] == -1) stack.push_back(static_cast<int>(i));
    while (!stack.empty()) {
        const int node = stack.back();
        stack.pop_back();
        reached[node] = true;
        for (int child : model.nodes[node].children) stack.push_back(child);
    }
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        if (reached[i]) continue;
        std::vector<bool> seen(model.nodes.size(), false);
        int node = static_cast<int>(i);
        while (!seen[node]) {
            seen[node] = true;
            node = parent[node];
        }
        context.fail(nodeName(model, node), "is its own ancestor (the children form a cycle)");
    }
}

void checkSceneRoots(const LoadContext& context, const tinygltf::Model& model, const std::vector<int>& parent) {
    for (std::size_t s = 0; s < model.scenes.size(); ++s) {
        std::set<int> listed;
        for (int root : model.scenes[s].nodes) {
            const std::string object = indexed("scenes", s);
            if (!listed.insert(root).second) context.fail(object, "lists " + nodeName(model, root) + " twice");
            if (parent[root] != -1)
                context.fail(object, "lists " + nodeName(model, root) + " as a root, but it is a child of " +
                                         nodeName(model, parent[root]));
        }
    }
}

} // namespace

void validateNodeGraph(const LoadContext& context, const tinygltf::Model& model) {
    for (std::size_t i = 0; i < model.nodes.size(); ++i) checkTransform(context, model, i);
    const std::vector<int> parent = assignParents(context, model);
    refuseCycles(context, model, parent);
    checkSceneRoots(context, model, parent);
}

} // namespace engine::gltf
