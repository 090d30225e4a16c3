// soak: renders many frames of one scene with an orbiting light and camera and a settings
// change every --change-every frames (every shadowed light's variant, map resolution and
// depth format, cycling through all combinations), and records the process's resident
// memory and the live GL objects (engine/gl/LiveObjects.h) over time. Prints the slope of
// both after the warm-up: a leak is a slope that does not go to zero.
#include "CommandLine.h"
#include "LinearFit.h"
#include "OptionValues.h"
#include "ToolMain.h"

#include "engine/config/EngineConfig.h"
#include "engine/gl/LiveObjects.h"
#include "engine/gltf/GltfLoader.h"
#include "engine/render/CameraSetup.h"
#include "engine/render/Renderer.h"
#include "engine/scene/SceneEdit.h"
#include "engine/util/OutputFile.h"
#include "engine/util/ProcessSetup.h"

#include "shadowmap/ShadowSettings.h"

#include <epoxy/gl.h>

#include <array>
#include <cstdio>
#include <malloc.h>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

const char* const kUsage =
    "usage: soak --config CONFIG.json --scene SCENE.gltf|.glb --out SAMPLES.csv\n"
    "  [--frames N (5000)] [--width W (320)] [--height H (180)]\n"
    "  [--change-every N (100)]  frames between settings changes\n"
    "  [--sample-every N (10)]   frames between samples of RSS and live GL objects\n"
    "  [--no-finish]             no glFinish after each frame (nothing waits for the GPU)\n"
    "  [--warmup N (1200)]       frames left out of the slopes: one period of the settings\n"
    "                            cycle (12 changes), caches filling, the allocator settling\n"
    "Writes one CSV row per sample (frame, rss_kib, heap_kib, textures, framebuffers, buffers, programs,\n"
    "shaders, samplers, vertex_arrays, queries, gl_objects) and prints the slopes after the warm-up.\n";

struct Options {
    bool help = false;
    std::string config, scene, out;
    bool finishFrames = true;
    int frames = 5000, width = 320, height = 180, changeEvery = 100, sampleEvery = 10, warmup = 1200;
};

Options parse(int argc, char** argv) {
    Options options;
    options.help = tools::parseFlags(argc, argv, {"--no-finish"}, [&](const std::string& flag, const std::string& value) {
        constexpr int kMany = 100'000'000;
        if (flag == "--config") options.config = value;
        else if (flag == "--scene") options.scene = value;
        else if (flag == "--out") options.out = value;
        else if (flag == "--frames") options.frames = tools::parseInteger(flag, value, 1, kMany);
        else if (flag == "--width") options.width = tools::parseInteger(flag, value, 1, 16384);
        else if (flag == "--height") options.height = tools::parseInteger(flag, value, 1, 16384);
        else if (flag == "--change-every") options.changeEvery = tools::parseInteger(flag, value, 1, kMany);
        else if (flag == "--sample-every") options.sampleEvery = tools::parseInteger(flag, value, 1, kMany);
        else if (flag == "--warmup") options.warmup = tools::parseInteger(flag, value, 0, kMany);
        else if (flag == "--no-finish") options.finishFrames = false;
        else return false;
        return true;
    });
    if (!options.help && (options.config.empty() || options.scene.empty() || options.out.empty()))
        throw std::invalid_argument("--config, --scene and --out are required");
    return options;
}

// Resident set size of this process in KiB (/proc/self/statm: pages).
long residentKib() {
    std::ifstream statm("/proc/self/statm");
    long size = 0, resident = 0;
    statm >> size >> resident;
    return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

// The settings of change number `change`: the variant cycles with period 4, the depth format
// steps every 4 changes (so 12 changes meet every variant with every format) and the
// resolution cycles with period 3. The whole pattern repeats every 12 changes (1200 frames
// by default): a warm-up of one period has made everything the cycle makes once, and a
// leak is what still grows after it.
nlohmann::json shadowSettings(int change) {
    using shadowmap::toString, shadowmap::Variant, shadowmap::DepthFormat;
    static const std::array<const char*, 4> variants{toString(Variant::Standard), toString(Variant::Woo),
                                                     toString(Variant::Backface), toString(Variant::None)};
    static const std::array<int, 3> resolutions{256, 512, 1024};
    static const std::array<const char*, 3> formats{toString(DepthFormat::D24), toString(DepthFormat::D16),
                                                    toString(DepthFormat::D32F)};
    return {{"variant", variants[change % 4]},
            {"resolution", resolutions[change % 3]},
            {"depth_format", formats[(change / 4) % 3]}};
}

// Bytes the C heap hands out now (in use, including its large mmapped blocks), in KiB. RSS
// also holds what the allocator keeps after a free (tuneAllocatorForRendering keeps up to
// 256 MiB on purpose) and the driver's own mappings; a leak of ours grows this one.
long heapInUseKib() {
    const struct mallinfo2 info = mallinfo2();
    return static_cast<long>((info.uordblks + info.hblkhd) / 1024);
}

struct Sample {
    int frame;
    long rssKib, heapKib;
    engine::gl::LiveObjectCounts objects;
};

int run(const Options& options, tools::ToolSession& session) {
    engine::tuneAllocatorForRendering();
    engine::checkOutputPath(options.out);  // before the soak's minutes, not after
    engine::Scene scene = engine::loadGltf(options.scene);
    if (scene.lightInstances.empty())
        throw engine::InputError(options.scene + ": no lights: nothing to orbit or to change settings of");
    const engine::EngineConfig config = engine::loadEngineConfig(options.config);
    session.context = engine::createEglContext();
    session.context->makeCurrent();
    session.host.loadAll(config);

    engine::Renderer renderer(config.renderer, session.host.renderPlugins());
    renderer.setScene(scene);
    engine::FrameRequest request;
    request.camera = engine::chooseCamera(scene, "", options.width, options.height, options.scene);

    const glm::dvec3 center = scene.worldBounds.empty() ? glm::dvec3(0.0) : scene.worldBounds.center();
    const int orbitingLight = scene.lightInstances.front().node;
    constexpr double kLightStep = 0.017453292519943295;   // 1 degree per frame
    constexpr double kCameraStep = 0.0087266462599716477; // half a degree per frame

    std::vector<Sample> samples;
    for (int frame = 0; frame < options.frames; ++frame) {
        if (frame % options.changeEvery == 0) {
            const nlohmann::json settings = shadowSettings(frame / options.changeEvery);
            for (engine::Light& light : scene.lights) light.extras["shadow"] = settings;
            renderer.reloadSettings();
        }
        engine::orbitNode(scene, orbitingLight, center, kLightStep);
        request.camera.eyeToWorld = engine::orbitTransform(request.camera.eyeToWorld, center, kCameraStep);
        renderer.renderFrame(request);
        // Each frame finished before the next, as a swap or a readback does in a real
        // application. Without it llvmpipe queues frame after frame of work that is never
        // waited for, and the heap grows with the queue, not with anything that leaks.
        if (options.finishFrames) glFinish();
        if ((frame + 1) % options.sampleEvery == 0)
            samples.push_back({frame + 1, residentKib(), heapInUseKib(), engine::gl::liveObjectCounts()});
    }

    std::ostringstream csv;
    csv << "frame,rss_kib,heap_kib,textures,framebuffers,buffers,programs,shaders,samplers,vertex_arrays,queries,gl_objects\n";
    std::vector<double> frames, rss, heap, objects;
    for (const Sample& s : samples) {
        const engine::gl::LiveObjectCounts& o = s.objects;
        csv << s.frame << ',' << s.rssKib << ',' << s.heapKib << ',' << o.textures << ',' << o.framebuffers << ',' << o.buffers << ','
            << o.programs << ',' << o.shaders << ',' << o.samplers << ',' << o.vertexArrays << ',' << o.queries << ',' << o.total() << '\n';
        if (s.frame <= options.warmup) continue;
        frames.push_back(s.frame);
        rss.push_back(static_cast<double>(s.rssKib));
        heap.push_back(static_cast<double>(s.heapKib));
        objects.push_back(static_cast<double>(o.total()));
    }
    engine::writeFileAtomically(options.out, csv.str());
    if (frames.size() < 2)
        throw engine::InputError("--warmup " + std::to_string(options.warmup) + " leaves fewer than two samples of " +
                                 std::to_string(options.frames) + " frames: nothing to fit");
    const Sample& last = samples.back();
    std::printf("soak: %d frames at %dx%d, settings changed every %d frames; after frame %d:\n"
                "  RSS          %+.1f KiB per 1000 frames (last %ld KiB)\n"
                "  heap in use  %+.1f KiB per 1000 frames (last %ld KiB)\n"
                "  GL objects   %+.3f per 1000 frames (last %lld: %lld textures, %lld framebuffers, "
                "%lld buffers, %lld programs)\n",
                options.frames, options.width, options.height, options.changeEvery, options.warmup,
                1000.0 * soak::leastSquaresSlope(frames, rss), last.rssKib,
                1000.0 * soak::leastSquaresSlope(frames, heap), last.heapKib,
                1000.0 * soak::leastSquaresSlope(frames, objects), static_cast<long long>(last.objects.total()),
                static_cast<long long>(last.objects.textures), static_cast<long long>(last.objects.framebuffers),
                static_cast<long long>(last.objects.buffers), static_cast<long long>(last.objects.programs));
    return 0;
}

} // namespace

int main(int argc, char** argv) { return tools::toolMain("soak", kUsage, argc, argv, parse, run); }
