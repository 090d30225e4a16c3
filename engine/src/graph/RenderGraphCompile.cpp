// compile(): cull, lifetimes and the aliasing plan. The order is the declaration order:
// every read names a version an earlier pass wrote (RenderGraph.h).
#include "engine/graph/RenderGraph.h"

#include <algorithm>

namespace engine {

namespace {
std::string quoted(const std::string& name) { return "'" + name + "'"; }
} // namespace

// ---- Culling ----------------------------------------------------------------------------
// Passes and resource versions form one bipartite graph (pass -> version it writes, version
// -> pass that reads it, version -> the layer or part write that keeps the rest of it). A node's
// reference count is its out-degree, plus one for side-effect passes and the latest version
// of an output. Nodes at zero are unused: popping one releases a reference on every node
// feeding it, which may drop to zero in turn. Whatever stays above zero survives.
std::vector<bool> RenderGraph::cull() {
    const int passCount = static_cast<int>(passes_.size());
    std::vector<int> firstNode;  // per resource: the node of its version 0
    int nodeCount = passCount;
    for (const Resource& resource : resources_) {
        firstNode.push_back(nodeCount);
        nodeCount += static_cast<int>(resource.versions.size());
    }
    std::vector<int> refs(nodeCount, 0);
    for (int p = 0; p < passCount; ++p) {
        refs[p] = static_cast<int>(passes_[p].writes.size()) + (passes_[p].sideEffect ? 1 : 0);
        for (std::size_t i = 0; i < passes_[p].reads.size(); ++i)
            ++refs[firstNode[passes_[p].reads[i]] + passes_[p].readVersions[i]];
    }
    for (std::size_t r = 0; r < resources_.size(); ++r) {
        const std::vector<Version>& versions = resources_[r].versions;
        if (resources_[r].output) ++refs[firstNode[r] + static_cast<int>(versions.size()) - 1];
        for (std::size_t v = 1; v < versions.size(); ++v)
            if (versions[v].keepsPrevious()) ++refs[firstNode[r] + static_cast<int>(v) - 1];
    }

    std::vector<int> unused;
    for (int node = 0; node < nodeCount; ++node)
        if (refs[node] == 0) unused.push_back(node);
    auto release = [&](int feeder) {
        if (--refs[feeder] == 0) unused.push_back(feeder);
    };
    while (!unused.empty()) {
        const int node = unused.back();
        unused.pop_back();
        if (node < passCount) {
            for (std::size_t i = 0; i < passes_[node].reads.size(); ++i)
                release(firstNode[passes_[node].reads[i]] + passes_[node].readVersions[i]);
            continue;
        }
        const int r = static_cast<int>(std::upper_bound(firstNode.begin(), firstNode.end(), node) - firstNode.begin()) - 1;
        const int v = node - firstNode[r];
        const Version& version = resources_[r].versions[v];
        if (version.writer >= 0) release(version.writer);
        if (version.keepsPrevious()) release(node - 1);
    }
    std::vector<bool> culled(passCount);
    for (int p = 0; p < passCount; ++p) culled[p] = refs[p] == 0;
    return culled;
}

// ---- Calculate resources lifetime -------------------------------------------------------
// A transient lives from its first to its last surviving user (positions in order_). The
// plan gives each a slot: processing by first use and reusing any free slot of equal desc is
// optimal for intervals (slots of one desc = the most transients of it alive at once).
void RenderGraph::planLifetimes() {
    for (Resource& resource : resources_) resource.firstUse = resource.lastUse = resource.slot = -1;
    for (int position = 0; position < static_cast<int>(order_.size()); ++position) {
        const Pass& pass = passes_[order_[position]];
        for (const auto* list : {&pass.reads, &pass.writes})
            for (int r : *list) {
                if (resources_[r].firstUse < 0) resources_[r].firstUse = position;
                resources_[r].lastUse = position;
            }
    }
    std::vector<int> transients;
    for (int r = 0; r < static_cast<int>(resources_.size()); ++r)
        if (!resources_[r].imported && resources_[r].firstUse >= 0) transients.push_back(r);
    std::stable_sort(transients.begin(), transients.end(),
                     [&](int a, int b) { return resources_[a].firstUse < resources_[b].firstUse; });
    struct Slot { TextureDesc desc; int lastUse; };
    std::vector<Slot> slots;
    for (int r : transients) {
        Resource& resource = resources_[r];
        auto free = std::find_if(slots.begin(), slots.end(), [&](const Slot& slot) {
            return slot.desc == resource.desc && slot.lastUse < resource.firstUse;
        });
        if (free == slots.end()) free = slots.insert(slots.end(), Slot{resource.desc, -1});
        free->lastUse = resource.lastUse;
        resource.slot = static_cast<int>(free - slots.begin());
    }
    slotCount_ = static_cast<int>(slots.size());
}

void RenderGraph::compile() {
    const std::vector<bool> culled = cull();
    order_.clear();
    for (int p = 0; p < static_cast<int>(passes_.size()); ++p)
        if (!culled[p]) order_.push_back(p);
    planLifetimes();

    reports_.assign(passes_.size(), PassReport{});
    for (std::size_t p = 0; p < passes_.size(); ++p) {
        reports_[p].name = passes_[p].name;
        for (std::size_t i = 0; i < passes_[p].reads.size(); ++i)
            reports_[p].reads.push_back(handleOf(passes_[p].reads[i], passes_[p].readVersions[i]));
    }
    for (std::size_t position = 0; position < order_.size(); ++position)
        reports_[order_[position]].order = static_cast<int>(position);
    for (std::size_t p = 0; p < passes_.size(); ++p) {
        if (!culled[p]) continue;
        PassReport& report = reports_[p];
        report.culled = true;
        if (passes_[p].writes.empty()) {
            report.cullReason = "writes nothing";
            continue;
        }
        // All it writes went unread by survivors; naming culled readers shows the chain.
        std::string names, culledReaders;
        for (int r : passes_[p].writes) {
            names += (names.empty() ? "" : " or ") + quoted(resources_[r].name);
            const std::vector<Version>& versions = resources_[r].versions;
            const int written = static_cast<int>(
                std::find_if(versions.begin(), versions.end(), [&](const Version& v) { return v.writer == static_cast<int>(p); }) -
                versions.begin());
            for (std::size_t q = 0; q < passes_.size(); ++q)
                for (std::size_t i = 0; i < passes_[q].reads.size(); ++i)
                    if (passes_[q].reads[i] == r && passes_[q].readVersions[i] == written)
                        culledReaders += (culledReaders.empty() ? "" : ", ") + quoted(passes_[q].name);
        }
        report.cullReason = "no surviving pass reads " + names;
        if (!culledReaders.empty()) report.cullReason += " (culled readers: " + culledReaders + ")";
    }
    compiled_ = true;
}

std::vector<std::string> RenderGraph::executionOrder() const {
    std::vector<std::string> names;
    for (int p : order_) names.push_back(passes_[p].name);
    return names;
}

int RenderGraph::physicalSlot(ResourceHandle resource) const {
    if (!owns(resource)) return -1;
    return resources_[resource.index].slot;
}

} // namespace engine
