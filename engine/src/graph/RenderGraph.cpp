// Declaring passes and resources (PassBuilder), and running the compiled graph (execute,
// PassContext). The analysis itself lives in RenderGraphCompile.cpp.
#include "engine/graph/RenderGraph.h"

#include <algorithm>
#include <atomic>
#include <chrono>

namespace engine {

namespace {
std::string quoted(const std::string& name) { return "'" + name + "'"; }
bool contains(const std::vector<int>& list, int value) {
    return std::find(list.begin(), list.end(), value) != list.end();
}
// Layers a single attachment may name: cube faces, array layers. A desc does not say whether
// a one-layer texture is an array, so its layer 0 passes here (GL refuses it for a plain 2D
// texture, and the renderer's GL error check names the pass).
int attachableLayers(const TextureDesc& desc) { return desc.cube ? kCubeFaces * desc.layers : desc.layers; }
} // namespace

// ---- declaration ----------------------------------------------------------------------

ResourceHandle RenderGraph::importTexture(const std::string& name, const TextureDesc& desc,
                                          std::uint32_t physical) {
    Resource resource{.name = name, .desc = desc, .imported = true, .physical = physical};
    return handleOf(addResource(std::move(resource), -1), 0);
}

std::uint64_t RenderGraph::nextSerial() {
    static std::atomic<std::uint64_t> serial{0};
    return ++serial;
}

bool RenderGraph::owns(ResourceHandle handle) const {
    return handle.graph == serial_ && handle.index >= 0 && handle.index < static_cast<int>(resources_.size());
}

int RenderGraph::addResource(Resource resource, int pass) {
    const std::string who = pass < 0 ? "import" : "pass " + quoted(passes_[pass].name);
    if (resource.name.empty()) throw GraphError(who + ": resource with an empty name");
    if (auto it = resourceByName_.find(resource.name); it != resourceByName_.end()) {
        const Resource& old = resources_[it->second];
        const std::string first =
            old.imported ? "imported" : "created by pass " + quoted(passes_[old.versions.front().writer].name);
        throw GraphError(who + ": resource " + quoted(resource.name) + " already " + first);
    }
    const TextureDesc& d = resource.desc;
    if (d.width <= 0 || d.height <= 0 || d.layers < 1 || (d.cube && d.width != d.height))
        throw GraphError(who + ": resource " + quoted(resource.name) + " has an invalid desc " + toString(d));
    resource.versions = {Version{pass, {}}};
    resourceByName_.emplace(resource.name, static_cast<int>(resources_.size()));
    resources_.push_back(std::move(resource));
    compiled_ = false;
    return static_cast<int>(resources_.size()) - 1;
}

const RenderGraph::Resource& RenderGraph::resourceAt(ResourceHandle handle, int pass) const {
    if (handle.valid() && handle.graph != 0 && handle.graph != serial_)
        throw GraphError("pass " + quoted(passes_[pass].name) + ": resource handle " + std::to_string(handle.index) +
                         " of another graph (kept from an earlier frame?)");
    if (!owns(handle) || handle.version < 0 ||
        handle.version >= static_cast<int>(resources_[handle.index].versions.size()))
        throw GraphError("pass " + quoted(passes_[pass].name) + ": invalid resource handle " +
                         std::to_string(handle.index) + " version " + std::to_string(handle.version));
    return resources_[handle.index];
}

// The physical texture holds only the latest version: a pass using an older one would see
// (or overwrite) what a later-declared write put there, which its declaration says it does
// not depend on.
void RenderGraph::checkLatest(ResourceHandle handle, int pass, const char* use) const {
    const Resource& resource = resources_[handle.index];
    const int newest = static_cast<int>(resource.versions.size()) - 1;
    if (handle.version == newest) return;
    const int overwriter = resource.versions[handle.version + 1].writer;
    throw GraphError("pass " + quoted(passes_[pass].name) + " " + use + " " + quoted(resource.name) + " version " +
                     std::to_string(handle.version) + ", but pass " + quoted(passes_[overwriter].name) +
                     " already wrote version " + std::to_string(handle.version + 1) +
                     ": use the handle that write returned");
}

PassId RenderGraph::addPass(std::string name, std::function<void(PassBuilder&)> setup,
                            std::function<void(PassContext&)> execute) {
    for (const Pass& pass : passes_)
        if (pass.name == name) throw GraphError("pass " + quoted(name) + " declared twice");
    passes_.push_back(Pass{.name = std::move(name), .execute = std::move(execute)});
    compiled_ = false;
    const int index = static_cast<int>(passes_.size()) - 1;
    const std::size_t resourceCount = resources_.size();
    try {
        PassBuilder builder(*this, index);
        if (setup) setup(builder);
    } catch (...) {
        // Roll back so a caller that catches the error still holds a consistent graph.
        for (std::size_t i = resourceCount; i < resources_.size(); ++i)
            resourceByName_.erase(resources_[i].name);
        resources_.resize(resourceCount);
        for (Resource& resource : resources_)
            std::erase_if(resource.versions, [index](const Version& version) { return version.writer == index; });
        passes_.pop_back();
        throw;
    }
    return PassId{index};
}

void RenderGraph::markOutput(ResourceHandle resource) {
    if (!owns(resource))
        throw GraphError("markOutput: resource handle " + std::to_string(resource.index) +
                         (resource.valid() && resource.graph != 0 && resource.graph != serial_ ? " of another graph"
                                                                                               : " invalid"));
    resources_[resource.index].output = true;
    compiled_ = false;
}

std::uint32_t RenderGraph::importedPhysical(ResourceHandle resource) const {
    if (!owns(resource)) return 0;
    const Resource& found = resources_[resource.index];
    return found.imported ? found.physical : 0;
}

const TextureDesc& RenderGraph::descOf(ResourceHandle resource) const {
    if (!owns(resource)) throw GraphError("descOf: resource handle " + std::to_string(resource.index) + " not of this graph");
    return resources_[resource.index].desc;
}

ResourceHandle PassBuilder::create(const std::string& name, const TextureDesc& desc) {
    RenderGraph::Resource resource{.name = name, .desc = desc};
    const int index = graph_.addResource(std::move(resource), pass_);
    graph_.passes_[pass_].writes.push_back(index);
    return graph_.handleOf(index, 0);
}

ResourceHandle PassBuilder::read(ResourceHandle handle) {
    const auto& resource = graph_.resourceAt(handle, pass_);
    auto& pass = graph_.passes_[pass_];
    // A texture sampled while it is drawn into is a feedback loop in GL, whichever
    // version the handles name.
    if (contains(pass.writes, handle.index))
        throw GraphError("pass " + quoted(pass.name) + " reads " + quoted(resource.name) +
                         ", which it writes itself");
    graph_.checkLatest(handle, pass_, "reads");
    if (!contains(pass.reads, handle.index)) {
        pass.reads.push_back(handle.index);
        pass.readVersions.push_back(handle.version);
    }
    return handle;
}

ResourceHandle PassBuilder::write(ResourceHandle handle) { return write(handle, -1); }

ResourceHandle PassBuilder::writePart(ResourceHandle handle) {
    const ResourceHandle written = write(handle, -1);
    graph_.resources_[written.index].versions.back().partial = true;
    return written;
}

ResourceHandle PassBuilder::write(ResourceHandle handle, int layer) {
    const auto& resource = graph_.resourceAt(handle, pass_);
    auto& pass = graph_.passes_[pass_];
    const std::string what = (layer < 0 ? "" : "layer " + std::to_string(layer) + " of ") + quoted(resource.name);
    if (layer >= attachableLayers(resource.desc))
        throw GraphError("pass " + quoted(pass.name) + " writes " + what + ", which has " +
                         std::to_string(attachableLayers(resource.desc)) + " layers (" + toString(resource.desc) + ")");
    const int newest = static_cast<int>(resource.versions.size()) - 1;
    RenderGraph::Version& latest = graph_.resources_[handle.index].versions.back();
    // This pass made the latest version already (its own transient, or another layer of
    // the same write): still that version, from the handle before or after its first write.
    if (latest.writer == pass_ && handle.version >= newest - 1) {
        if (layer < 0)
            latest.layers.clear();
        else if (!latest.layers.empty() && !contains(latest.layers, layer))
            latest.layers.push_back(layer);
        return graph_.latest(handle.index);
    }
    graph_.checkLatest(handle, pass_, "writes");
    if (contains(pass.reads, handle.index))
        throw GraphError("pass " + quoted(pass.name) + " writes " + quoted(resource.name) +
                         ", which it reads itself");
    graph_.resources_[handle.index].versions.push_back(
        {pass_, layer < 0 ? std::vector<int>{} : std::vector<int>{layer}});
    pass.writes.push_back(handle.index);
    return graph_.latest(handle.index);
}

void PassBuilder::sideEffect() { graph_.passes_[pass_].sideEffect = true; }

void PassBuilder::setState(const PassState& state) { graph_.passes_[pass_].state = state; }

void PassBuilder::setTargets(const PassTargets& targets) {
    auto& pass = graph_.passes_[pass_];
    auto check = [&](ResourceHandle handle, int layer, const char* kind) {
        const auto& resource = graph_.resourceAt(handle, pass_);
        const std::string what = std::string(kind) + " target " + quoted(resource.name) +
                                 (layer < 0 ? "" : " layer " + std::to_string(layer));
        if (!contains(pass.writes, handle.index))
            throw GraphError("pass " + quoted(pass.name) + ": " + what + " is not written by the pass");
        if (layer >= attachableLayers(resource.desc))
            throw GraphError("pass " + quoted(pass.name) + ": " + what + " is out of range (" +
                             toString(resource.desc) + ")");
        // A pass that writes only some layers may draw into only those.
        const bool allowed = std::any_of(resource.versions.begin(), resource.versions.end(), [&](const auto& version) {
            return version.writer == pass_ && (version.layers.empty() || contains(version.layers, layer));
        });
        if (!allowed) throw GraphError("pass " + quoted(pass.name) + ": " + what + " is not a layer the pass writes");
    };
    for (const ColorTarget& color : targets.colors) check(color.resource, color.layer, "colour");
    if (targets.depth.resource.valid()) check(targets.depth.resource, targets.depth.layer, "depth");
    pass.targets = targets;
}

// ---- execution --------------------------------------------------------------------------

const RenderGraph::Resource& RenderGraph::declaredBy(ResourceHandle handle, int pass) const {
    const Resource& resource = resourceAt(handle, pass);
    const Pass& p = passes_[pass];
    if (!contains(p.reads, handle.index) && !contains(p.writes, handle.index))
        throw GraphError("pass " + quoted(p.name) + " uses " + quoted(resource.name) +
                         " without declaring it in setup");
    return resource;
}

std::uint32_t PassContext::texture(ResourceHandle resource) const {
    return graph_.declaredBy(resource, pass_).physical;
}

const TextureDesc& PassContext::desc(ResourceHandle resource) const {
    return graph_.declaredBy(resource, pass_).desc;
}

void PassContext::countDraw(std::uint64_t triangles) {
    report_.draws += 1;
    report_.triangles += triangles;
}

void PassContext::countCulledDraw() { report_.drawsCulled += 1; }

const std::string& PassContext::passName() const { return graph_.passes_[pass_].name; }

PassState RenderGraph::resolvedState(const Pass& pass) const {
    PassState state = pass.state;
    const PassTargets& targets = pass.targets;
    const int sized = !targets.colors.empty()            ? targets.colors.front().resource.index
                      : targets.depth.resource.valid()  ? targets.depth.resource.index
                      : !pass.writes.empty()            ? pass.writes.front()
                                                        : -1;
    if (state.viewportWidth == 0 && state.viewportHeight == 0 && sized >= 0) {
        const TextureDesc& target = resources_[sized].desc;
        state.viewportWidth = target.width;
        state.viewportHeight = target.height;
    }
    return state;
}

void RenderGraph::execute(ResourceAllocator& allocator, const ExecuteOptions& options) {
    if (!compiled_) compile();
    std::vector<std::vector<int>> acquireAt(order_.size()), releaseAt(order_.size());
    for (int r = 0; r < static_cast<int>(resources_.size()); ++r) {
        if (resources_[r].imported || resources_[r].firstUse < 0) continue;
        acquireAt[resources_[r].firstUse].push_back(r);
        releaseAt[resources_[r].lastUse].push_back(r);
    }
    std::vector<int> held;  // acquired and not yet released: given back if a pass throws
    auto release = [&](int r) {
        allocator.release(resources_[r].physical, resources_[r].desc);
        resources_[r].physical = 0;
        held.erase(std::find(held.begin(), held.end(), r));
    };
    for (PassReport& report : reports_) report.wallMs = 0, report.draws = report.triangles = report.drawsCulled = 0;
    try {
        for (std::size_t position = 0; position < order_.size(); ++position) {
            for (int r : acquireAt[position]) {
                resources_[r].physical = allocator.acquire(resources_[r].desc);
                held.push_back(r);
            }
            const int index = order_[position];
            PassContext context(*this, index, reports_[index]);
            const auto start = std::chrono::steady_clock::now();
            const PassState state = resolvedState(passes_[index]);
            if (options.applyState) options.applyState(state);
            if (options.bindTargets) options.bindTargets(passes_[index].targets, state, context);
            if (passes_[index].execute) passes_[index].execute(context);
            if (options.timing) {
                if (options.finish) options.finish();
                const std::chrono::duration<double, std::milli> elapsed =
                    std::chrono::steady_clock::now() - start;
                reports_[index].wallMs = elapsed.count();
            }
            if (options.afterPass) options.afterPass(passes_[index].name);
            for (int r : releaseAt[position]) release(r);
        }
    } catch (...) {
        while (!held.empty()) release(held.back());
        throw;
    }
}

} // namespace engine
