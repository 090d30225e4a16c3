#pragma once
// The render-pass graph: each frame, modules add passes that declare which textures they
// create, read and write; compile() culls what no output needs, orders the rest and plans
// transient textures; execute() runs the survivors. No GL here: physical textures come from a
// ResourceAllocator, so the whole algorithm is unit-tested without a context.
//
// Contract (plugins and tools rely on it):
// - Resources are textures with names unique in the graph. A transient is made by create()
//   in one pass; an import (importTexture) is owned elsewhere (persistent shadow maps, the
//   final target). Resources are reached only through handles: names are for Graphviz and
//   messages.
// - Handles are versioned (as Filament's FrameGraphId): create and import give version 0;
//   write() gives a handle to the next version, which later passes must use. A write of
//   one layer (a cube face, an array layer) keeps the other layers of the version before,
//   so a reader of the last face's version needs every face pass; a whole write does not.
//   One pass writing several layers of a resource makes one version. A pass that reads or
//   writes a version older than the latest (a handle kept from before another pass's write)
//   is a GraphError naming both passes: the texture holds the newer contents by then.
// - Reads see the version their handle names, so every dependency points to an earlier
//   declaration: execution keeps declaration order, and no cycle can be declared. An import
//   nobody writes is a valid input (its contents come from outside).
// - A duplicate name, an invalid handle or one another graph returned (kept from an earlier
//   frame), or a pass reading what it writes is a GraphError naming the pass(es) and the
//   resource.
// - A pass's fixed-function state (PassState.h) and the targets it draws into (PassTargets.h)
//   are declared with it and applied by the executor, in that order, before it runs.
// - Culling counts references back from the outputs (as Filament's FrameGraph), version by
//   version: a pass survives if it has a side effect, writes the latest version of a
//   resource marked output, or writes a version a surviving pass reads (or a later layer
//   write builds on). Culled passes never execute, their transients are never acquired, and
//   reports() gives the reason.
// - Transients are acquired right before their first user executes and released right after
//   their last user, so the allocator can reuse a texture within the frame. compile() also
//   plans that reuse statically (physicalSlot / physicalSlotCount): transients of equal desc
//   with disjoint lifetimes share one slot. To keep contents past the frame, import instead.
#include "engine/graph/PassId.h"
#include "engine/graph/PassState.h"
#include "engine/graph/PassTargets.h"
#include "engine/graph/ResourceAllocator.h"
#include "engine/graph/ResourceHandle.h"
#include "engine/graph/TextureDesc.h"

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace engine {

class RenderGraph;

class GraphError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Handed to a pass's setup callback: the pass declares its resources through it.
class PassBuilder {
public:
    // A transient texture this pass writes; the name must be new to the graph.
    [[nodiscard]] ResourceHandle create(const std::string& name, const TextureDesc& desc);
    // `resource` must name the latest version.
    ResourceHandle read(ResourceHandle resource);
    // Writes the whole texture: returns the handle of the version this pass makes (the
    // creator writing its own transient keeps version 0).
    [[nodiscard]] ResourceHandle write(ResourceHandle resource);
    // Writes one layer (array layer or cube face); the other layers keep their contents.
    [[nodiscard]] ResourceHandle write(ResourceHandle resource, int layer);
    // Writes part of the texture (a viewport's rectangle, PassState::scissorToViewport): the
    // rest keeps its contents, so the version before lives as long as this one is needed (a
    // shadow atlas's maps, each rendered by its own pass).
    [[nodiscard]] ResourceHandle writePart(ResourceHandle resource);
    void sideEffect();  // never culled (e.g. a readback)
    // The state the pass's draws start from (PassState.h); PassState{} when not declared.
    void setState(const PassState& state);
    // What the pass draws into (PassTargets.h): textures, and layers, it writes.
    void setTargets(const PassTargets& targets);

private:
    friend class RenderGraph;
    PassBuilder(RenderGraph& graph, int pass) : graph_(graph), pass_(pass) {}
    RenderGraph& graph_;
    int pass_;
};

struct PassReport {
    std::string name;
    bool culled = false;
    std::string cullReason;  // e.g. "no surviving pass reads 'shadow_map_light2'"
    int order = -1;          // position in execution order, -1 when culled
    double wallMs = 0;       // only measured with ExecuteOptions::timing
    std::uint64_t draws = 0, triangles = 0;
    std::uint64_t drawsCulled = 0;  // objects the pass left out as outside its view
    std::vector<ResourceHandle> reads;  // what the pass declared it reads, at the versions it read
};

// Handed to a pass's execute callback.
class PassContext {
public:
    // Physical handle (a GL texture name in practice) of a resource this pass declared.
    std::uint32_t texture(ResourceHandle resource) const;
    const TextureDesc& desc(ResourceHandle resource) const;
    void countDraw(std::uint64_t triangles);  // one draw call of that many triangles
    void countCulledDraw();                   // one object left out as outside the view
    const std::string& passName() const;

private:
    friend class RenderGraph;
    PassContext(const RenderGraph& graph, int pass, PassReport& report)
        : graph_(graph), pass_(pass), report_(report) {}
    const RenderGraph& graph_;
    int pass_;
    PassReport& report_;
};

struct ExecuteOptions {
    bool timing = false;
    // Called after each pass when timing (glFinish in practice): GL work is asynchronous,
    // so without it a pass's wall time would measure command submission, not the work.
    std::function<void()> finish;
    // Called before each pass runs, with its declared state (the viewport filled in from the
    // first texture it writes when left 0).
    std::function<void(const PassState&)> applyState;
    // Called after applyState: binds the pass's declared targets (none: the default
    // framebuffer) and clears what they ask to, under the pass's state.
    std::function<void(const PassTargets&, const PassState&, const PassContext&)> bindTargets;
    // Called after each pass has run (after finish, when timing), with its name: e.g. a GL
    // error check that blames the pass that raised the flag. May throw; the frame stops.
    std::function<void(const std::string& passName)> afterPass;
};

class RenderGraph {
public:
    ResourceHandle importTexture(const std::string& name, const TextureDesc& desc,
                                 std::uint32_t physical);
    // setup runs now (declaring resources); execute runs in execute(), if not culled.
    PassId addPass(std::string name, std::function<void(PassBuilder&)> setup,
                   std::function<void(PassContext&)> execute);
    void markOutput(ResourceHandle resource);  // presented or exported: keeps its writer alive
    void compile();                            // throws GraphError
    void execute(ResourceAllocator& allocator, const ExecuteOptions& options = {});  // compiles if needed

    const std::vector<PassReport>& reports() const { return reports_; }  // declaration order
    // Compiled graph in DOT: passes boxes, resources ellipses, culled passes dashed grey with
    // their reason, imports filled, outputs double-bordered.
    std::string graphviz() const;

    // Introspection (valid after compile()).
    // An import's physical handle and description (for reading a map back after the frame,
    // e.g. a debug view); 0 for transients, whose textures go back to the allocator.
    std::uint32_t importedPhysical(ResourceHandle resource) const;
    const TextureDesc& descOf(ResourceHandle resource) const;
    std::vector<std::string> executionOrder() const;      // surviving pass names
    int physicalSlotCount() const { return slotCount_; }  // textures the aliasing plan needs
    int physicalSlot(ResourceHandle resource) const;      // -1 for imports and unused transients

private:
    friend class PassBuilder;
    friend class PassContext;

    struct Pass {
        std::string name;
        std::function<void(PassContext&)> execute;
        std::vector<int> reads{}, writes{};  // resource indices; writes include creates
        std::vector<int> readVersions{};     // beside reads
        bool sideEffect = false;
        PassState state{};
        PassTargets targets{};
    };
    struct Version {
        int writer = -1;            // the pass that made it; -1: an import as it comes in
        std::vector<int> layers{};  // the layers written; empty: the whole texture
        bool partial = false;       // writePart: a rectangle, the rest kept
        // Whether the version before still shows in this one.
        bool keepsPrevious() const { return partial || !layers.empty(); }
    };
    struct Resource {
        std::string name;
        TextureDesc desc;
        bool imported = false, output = false;
        std::vector<Version> versions{};  // [0]: as created or imported; one per write after
        std::uint32_t physical = 0;  // an import's handle; a transient's while acquired
        int firstUse = -1, lastUse = -1;  // positions in order_, from compile()
        int slot = -1;                    // aliasing plan, from compile()
    };

    static std::uint64_t nextSerial();
    // Whether `handle` names a resource of this graph.
    bool owns(ResourceHandle handle) const;
    ResourceHandle handleOf(int index, int version) const { return {index, serial_, version}; }
    ResourceHandle latest(int index) const {
        return handleOf(index, static_cast<int>(resources_[index].versions.size()) - 1);
    }
    int addResource(Resource resource, int pass);
    const Resource& resourceAt(ResourceHandle handle, int pass) const;
    // Throws unless `handle` names the latest version; `use` is "reads" or "writes".
    void checkLatest(ResourceHandle handle, int pass, const char* use) const;
    const Resource& declaredBy(ResourceHandle handle, int pass) const;  // PassContext's check
    PassState resolvedState(const Pass& pass) const;                    // viewport filled in
    std::vector<bool> cull();
    void planLifetimes();

    std::uint64_t serial_ = nextSerial();  // in every handle this graph returns
    std::vector<Pass> passes_;
    std::vector<Resource> resources_;
    std::unordered_map<std::string, int> resourceByName_;
    bool compiled_ = false;
    std::vector<int> order_;  // surviving pass indices in execution order
    std::vector<PassReport> reports_;
    int slotCount_ = 0;
};

} // namespace engine
