// compile(): order (rejecting cycles), cull, lifetimes and the aliasing plan.
#include "engine/graph/RenderGraph.h"

#include <algorithm>
#include <set>

namespace engine {

namespace {
std::string quoted(const std::string& name) { return "'" + name + "'"; }
} // namespace

// ---- Order ------------------------------------------------------------------------------
// Kahn's algorithm over every pass (culled or not: a cycle is a bug in the declarations
// either way, and reference counting cannot cull a cycle). Always taking the ready pass
// declared first keeps the order stable. Passes left over sit on or behind a cycle; walking
// back through their unfinished predecessors must revisit one, which yields the cycle.
std::vector<int> RenderGraph::topologicalOrder() const {
    const int passCount = static_cast<int>(passes_.size());
    struct Edge { int pass, resource; };  // the pass at the other end, through the resource
    std::vector<std::vector<Edge>> successors(passCount), predecessors(passCount);
    std::vector<int> inDegree(passCount, 0);
    for (int reader = 0; reader < passCount; ++reader)
        for (int r : passes_[reader].reads)
            for (const Writer& writer : resources_[r].writers) {
                successors[writer.pass].push_back({reader, r});
                predecessors[reader].push_back({writer.pass, r});
                ++inDegree[reader];
            }

    std::set<int> ready;
    for (int p = 0; p < passCount; ++p)
        if (inDegree[p] == 0) ready.insert(p);
    std::vector<int> order;
    while (!ready.empty()) {
        const int p = *ready.begin();
        ready.erase(ready.begin());
        order.push_back(p);
        for (const Edge& edge : successors[p])
            if (--inDegree[edge.pass] == 0) ready.insert(edge.pass);
    }
    if (static_cast<int>(order.size()) == passCount) return order;

    int p = static_cast<int>(std::find_if(inDegree.begin(), inDegree.end(),
                                          [](int d) { return d > 0; }) - inDegree.begin());
    // path[i]: pass path[i].reader reads resource path[i].resource, written by path[i].writer
    struct Step { int reader, resource, writer; };
    std::vector<Step> path;
    std::vector<int> seenAt(passCount, -1);
    while (seenAt[p] < 0) {
        seenAt[p] = static_cast<int>(path.size());
        const Edge& back = *std::find_if(predecessors[p].begin(), predecessors[p].end(),
                                         [&](const Edge& e) { return inDegree[e.pass] > 0; });
        path.push_back({p, back.resource, back.pass});
        p = back.pass;
    }
    std::string message = "render graph has a cycle:";
    for (int i = static_cast<int>(path.size()) - 1; i >= seenAt[p]; --i) {
        const Resource& resource = resources_[path[i].resource];
        message += " pass " + quoted(passes_[path[i].writer].name) + " writes " +
                   quoted(resource.name) + ", read by pass " + quoted(passes_[path[i].reader].name) +
                   (i > seenAt[p] ? ";" : "");
    }
    throw GraphError(message);
}

// ---- Culling ----------------------------------------------------------------------------
// Passes and resources form one bipartite graph (pass -> resource it writes, resource -> pass
// that reads it). A node's reference count is its out-degree, plus one for side-effect
// passes and output resources. Nodes at zero are unused: popping one releases a reference on
// every node feeding it, which may drop to zero in turn. Whatever stays above zero survives.
std::vector<bool> RenderGraph::cull() {
    const int passCount = static_cast<int>(passes_.size());
    const int nodeCount = passCount + static_cast<int>(resources_.size());
    std::vector<int> refs(nodeCount, 0);
    for (int p = 0; p < passCount; ++p) {
        refs[p] = static_cast<int>(passes_[p].writes.size()) + (passes_[p].sideEffect ? 1 : 0);
        for (int r : passes_[p].reads) ++refs[passCount + r];
    }
    for (std::size_t r = 0; r < resources_.size(); ++r)
        if (resources_[r].output) ++refs[passCount + r];

    std::vector<int> unused;
    for (int node = 0; node < nodeCount; ++node)
        if (refs[node] == 0) unused.push_back(node);
    while (!unused.empty()) {
        const int node = unused.back();
        unused.pop_back();
        auto release = [&](int feeder) {
            if (--refs[feeder] == 0) unused.push_back(feeder);
        };
        if (node < passCount) {
            for (int r : passes_[node].reads) release(passCount + r);
        } else {
            for (const Writer& writer : resources_[node - passCount].writers) release(writer.pass);
        }
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
    const std::vector<int> order = topologicalOrder();
    const std::vector<bool> culled = cull();
    order_.clear();
    for (int p : order)
        if (!culled[p]) order_.push_back(p);
    planLifetimes();

    reports_.assign(passes_.size(), PassReport{});
    for (std::size_t p = 0; p < passes_.size(); ++p) {
        reports_[p].name = passes_[p].name;
        for (const int r : passes_[p].reads) reports_[p].reads.push_back(handleOf(r));
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
            for (std::size_t q = 0; q < passes_.size(); ++q)
                if (std::find(passes_[q].reads.begin(), passes_[q].reads.end(), r) != passes_[q].reads.end())
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
