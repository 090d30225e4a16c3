#pragma once
// The render-pass graph: each frame, modules add passes that declare which textures they
// create, read and write; compile() culls what no output needs, orders the rest and plans
// transient textures; execute() runs the survivors. No GL here: physical textures come from a
// ResourceAllocator, so the whole algorithm is unit-tested without a context.
//
// Contract (plugins and tools rely on it):
// - Resources are textures with names unique in the graph. A transient is made by create()
//   in exactly one pass, its writer. An import (importTexture) is owned elsewhere (persistent
//   shadow maps, the final target) and is written either whole by at most one pass, via
//   write(), or layer by layer (cube faces, array layers) by several passes, each writing
//   layers no other pass writes, via write(resource, layer).
//   A duplicate name, a second writer of the same texels, an invalid handle or one another
//   graph returned (kept from an earlier frame), or a pass reading what it writes is a
//   GraphError naming the pass(es) and the resource. Resources are reached only through
//   the handles their creators returned: names are for Graphviz and messages.
// - Dependencies run from a resource's writers to every reader, whatever the declaration
//   order: a pass reading an import that other passes write runs after all of them and sees
//   this frame's contents. An import nobody writes is a valid input (its contents come from
//   outside). Cycles are a GraphError naming the passes in them.
// - A pass's fixed-function state (PassState.h) and the targets it draws into (PassTargets.h)
//   are declared with it and applied by the executor, in that order, before it runs.
// - Culling counts references back from the outputs (as Filament's FrameGraph): a pass
//   survives if it has a side effect, writes a resource marked output, or writes something a
//   surviving pass reads. Culled passes never execute, their transients are never acquired,
//   and reports() gives the reason.
// - Order: topological and stable (ties keep declaration order), so output is reproducible.
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
    ResourceHandle read(ResourceHandle resource);
    // Declares this pass the writer of an import (or returns its own transient unchanged).
    [[nodiscard]] ResourceHandle write(ResourceHandle resource);
    // Declares this pass the writer of one layer (array layer or cube face) of an import;
    // other passes may write its other layers.
    [[nodiscard]] ResourceHandle write(ResourceHandle resource, int layer);
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
    std::vector<ResourceHandle> reads;  // what the pass declared it reads
};

// Handed to a pass's execute callback.
class PassContext {
public:
    // Physical handle (a GL texture name in practice) of a resource this pass declared.
    std::uint32_t texture(ResourceHandle resource) const;
    const TextureDesc& desc(ResourceHandle resource) const;
    void countDraw(std::uint64_t triangles);  // one draw call of that many triangles
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
        bool sideEffect = false;
        PassState state{};
        PassTargets targets{};
    };
    struct Writer {
        int pass = -1;
        int layer = -1;  // -1: the whole texture
    };
    struct Resource {
        std::string name;
        TextureDesc desc;
        bool imported = false, output = false;
        std::vector<Writer> writers{};  // one whole writer, or one per written layer
        std::uint32_t physical = 0;  // an import's handle; a transient's while acquired
        int firstUse = -1, lastUse = -1;  // positions in order_, from compile()
        int slot = -1;                    // aliasing plan, from compile()
    };

    static std::uint64_t nextSerial();
    // Whether `handle` names a resource of this graph.
    bool owns(ResourceHandle handle) const;
    ResourceHandle handleOf(int index) const { return {index, serial_}; }
    int addResource(Resource resource, int pass);
    const Resource& resourceAt(ResourceHandle handle, int pass) const;
    const Resource& declaredBy(ResourceHandle handle, int pass) const;  // PassContext's check
    std::vector<int> topologicalOrder() const;                          // throws on cycles
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
