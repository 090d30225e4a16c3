// Scene graph traversal: composes world transforms in double and gathers the instances
// every pass works from (M: object -> world, see Scene.h).
#include "engine/scene/Scene.h"

#include "engine/scene/Deform.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cassert>
#include <numeric>
#include <unordered_map>
#include <utility>

namespace engine {

glm::dmat4 Node::trsMatrix() const {
    return glm::scale(glm::translate(glm::dmat4(1.0), translation) * glm::mat4_cast(rotation), scale);
}

std::size_t Mesh::triangleCount() const {
    return std::accumulate(primitives.begin(), primitives.end(), std::size_t{0},
                           [](std::size_t sum, const Primitive& p) { return sum + p.triangleCount(); });
}

namespace {

// World transforms of nodes the displayed scene does not reach (a skin's joints may lie
// outside it): composed up their parent chains, each node once.
void composeUnvisitedWorlds(std::vector<Node>& nodes, std::vector<bool> done) {
    std::vector<int> chain;
    for (std::size_t start = 0; start < nodes.size(); ++start) {
        chain.clear();
        for (int n = static_cast<int>(start); n >= 0 && !done[n]; n = nodes[n].parent) {
            chain.push_back(n);
            done[n] = true;  // also ends the walk if a hand-built scene has a parent cycle
        }
        for (auto n = chain.rbegin(); n != chain.rend(); ++n) {
            const Node& node = nodes[*n];
            nodes[*n].world = node.parent >= 0 ? nodes[node.parent].world * node.local : node.local;
        }
    }
}

} // namespace

void Scene::updateWorldTransforms() {
    // The previous call's instances by node, to carry revisions of instances that stayed put.
    std::unordered_map<int, const MeshInstance*> previousByNode;
    const std::vector<MeshInstance> previous = std::move(meshInstances);
    for (const MeshInstance& instance : previous) previousByNode.emplace(instance.node, &instance);
    meshInstances.clear();
    lightInstances.clear();
    cameraInstances.clear();
    worldBounds = Aabb{};

    // An explicit stack rather than recursion: a hostile file may chain thousands of nodes.
    // Children are pushed in reverse so the visit order is the usual depth-first preorder.
    struct Pending {
        int node;
        glm::dmat4 parentWorld;
    };
    std::vector<Pending> stack;
    std::vector<bool> visited(nodes.size(), false);
    for (auto root = roots.rbegin(); root != roots.rend(); ++root)
        stack.push_back({*root, glm::dmat4(1.0)});

    while (!stack.empty()) {
        const Pending pending = stack.back();
        stack.pop_back();
        assert(pending.node >= 0 && static_cast<std::size_t>(pending.node) < nodes.size());
        // The loader rejects cycles and shared children; a hand-built scene that has them is
        // a bug, but must not hang the engine.
        assert(!visited[pending.node] && "node reached twice: cycle or two parents");
        if (visited[pending.node]) continue;
        visited[pending.node] = true;

        Node& node = nodes[pending.node];
        node.world = pending.parentWorld * node.local;

        if (node.mesh >= 0) {
            assert(static_cast<std::size_t>(node.mesh) < meshes.size());
            MeshInstance instance;
            instance.node = pending.node;
            instance.mesh = node.mesh;
            instance.world = node.world;
            instance.worldBounds = meshes[node.mesh].bounds.transformed(node.world);
            instance.castShadows = node.castShadows;
            instance.receiveShadows = node.receiveShadows;
            meshInstances.push_back(instance);
        }
        if (node.light >= 0) {
            assert(static_cast<std::size_t>(node.light) < lights.size());
            lightInstances.push_back({pending.node, node.light, node.world});
        }
        if (node.camera >= 0) {
            assert(static_cast<std::size_t>(node.camera) < cameras.size());
            cameraInstances.push_back({pending.node, node.camera, node.world});
        }
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
            stack.push_back({*child, node.world});
    }
    composeUnvisitedWorlds(nodes, visited);

    // Deformed instances after the traversal: a skin's joints may come after its mesh.
    for (MeshInstance& instance : meshInstances) {
        const Node& node = nodes[instance.node];
        const auto before = previousByNode.find(instance.node);
        const MeshInstance* previousInstance = before != previousByNode.end() ? before->second : nullptr;
        if (isDeformed(*this, node)) {
            auto deformed = std::make_shared<const DeformedMesh>(deformMesh(*this, node));
            // Keep the previous pose's object when the vertices did not move, so the GPU
            // copy and the revision stay.
            if (previousInstance && previousInstance->deformed && *previousInstance->deformed == *deformed)
                deformed = previousInstance->deformed;
            if (node.skin >= 0) instance.world = glm::dmat4(1.0);
            instance.worldBounds = deformed->bounds.transformed(instance.world);
            instance.deformed = std::move(deformed);
        }
        const bool unchanged = previousInstance && previousInstance->mesh == instance.mesh &&
                               previousInstance->world == instance.world &&
                               previousInstance->deformed == instance.deformed;
        instance.revision = unchanged ? previousInstance->revision : ++lastInstanceRevision;
        worldBounds.extend(instance.worldBounds);
    }
}

namespace {

// Index of the first instance whose object (light or camera) is called `name`, else of the
// first whose node is: glTF lights and cameras are often unnamed while their nodes are not.
template <typename Instance, typename Object>
int findInstanceByName(const std::vector<Instance>& instances, const std::vector<Object>& objects,
                       int Instance::*objectIndex, const std::vector<Node>& nodes,
                       const std::string& name) {
    for (std::size_t i = 0; i < instances.size(); ++i)
        if (objects[instances[i].*objectIndex].name == name) return static_cast<int>(i);
    for (std::size_t i = 0; i < instances.size(); ++i)
        if (nodes[instances[i].node].name == name) return static_cast<int>(i);
    return -1;
}

} // namespace

int Scene::findLightInstance(const std::string& name) const {
    return findInstanceByName(lightInstances, lights, &LightInstance::light, nodes, name);
}

int Scene::findCameraInstance(const std::string& name) const {
    return findInstanceByName(cameraInstances, cameras, &CameraInstance::camera, nodes, name);
}

} // namespace engine
