#pragma once
// Automatic exposure (engine-render and engine-view --exposure auto): the exposure that maps
// the scene's log-average luminance to middle grey, the key 0.18 of Reinhard et al.'s
// photographic tone reproduction (SIGGRAPH 2002): exposure = 0.18 / L_avg, with
// L_avg = exp(mean of ln L) over the pixels, L the linear luminance of the shaded radiance
// before exposure and tone mapping (Rec. 709 weights: 0.2126 R + 0.7152 G + 0.0722 B).
//
// The radiance is measured from probe renders of the frame itself (same scene, lights,
// shadows and camera), read back as the renderer writes them: radiance x exposure, clamped
// at 1, sRGB-encoded to 8 bits, with tone mapping off and a black background. Below 1 that
// encoding is invertible (a code's sRGB decoding divided by the probe's exposure), so the
// probes form a bracket: exposures kProbeStepEv stops apart, from the brightest --exposure
// takes (kMinEv100) down until nothing saturates (at most to kMaxEv100), and each pixel is
// read from the brightest probe that does not saturate it (its brightest channel a code of at
// least 12 there, as the probe before saturated it: at most about 5 % of rounding per pixel,
// unbiased, which the mean over many pixels averages out).
// Pixels black in the brightest probe (the background, or a black surface with nothing
// lighting it) have no luminance to average (ln 0): they are left out, where Reinhard adds a
// small delta instead, which would make the result depend on that delta and on how much
// background is in view.
#include "engine/config/EngineConfig.h"
#include "engine/plugin/RenderPlugin.h"
#include "engine/render/Frame.h"
#include "engine/scene/Scene.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tools {

constexpr double kMiddleGrey = 0.18;
// --exposure's value that asks for it.
constexpr const char* kAutoExposureWord = "auto";
// --exposure EV100's bounds in engine-render and engine-view, from a moonless night to well
// past the sun (15): bounds on typos, not on scenes. The bracket of probes spans them too.
constexpr double kMinEv100 = -10.0, kMaxEv100 = 30.0;
// From one probe to the next, in stops: 8 keeps a pixel that saturated one probe at a code
// of 12 or more in the next (2^-8 of full scale, sRGB-encoded), and needs at most 6 probes.
constexpr double kProbeStepEv = 8.0;

struct ExposureProbe {
    float exposure = 1.0f;            // the radiance was multiplied by it before the 8-bit encoding
    std::vector<std::uint8_t> rgba;   // sRGB-encoded, clamped at 1
};

struct MeteredScene {
    double logAverage = 0.0;    // exp(mean ln L) over the measured pixels (0 when none)
    std::size_t pixels = 0;     // measured: not black in the brightest probe
    std::size_t saturated = 0;  // saturated in every probe (their L a lower bound)
};

// Whether a probe saturates some pixel: a channel at 255.
bool probeSaturates(const std::vector<std::uint8_t>& rgba);

// The log-average luminance of `probes` (the same frame, brightest exposure first), each
// pixel read from the brightest probe it does not saturate (else the last one).
MeteredScene meterProbes(const std::vector<ExposureProbe>& probes);

// The EV100 whose exposure (engine::exposureFromEv100) maps `logAverage` to kMiddleGrey:
// log2(logAverage / (1.2 * 0.18)).
double ev100ForLogAverage(double logAverage);

struct AutoExposure {
    bool measured = false;  // false: nothing lit in view; the config's exposure stays
    double ev100 = 0.0;
    float exposure = 1.0f;  // engine::exposureFromEv100(ev100), else the config's
    MeteredScene metered;
    int probes = 0;
};

// Renders the probes of `camera`'s frame of `scene` (a Renderer of its own per probe, made
// from `config` with exposure, tone mapping and background changed; the plugins' per-light
// settings as they are), and meters them. Needs a current GL context and no other Renderer
// drawing with `plugins` in between: the caller makes its own afterwards (setScene again).
// The probes are rendered at most kProbeSide pixels on the longer side, the same view: the
// log-average is a mean, which a tenth of the pixels estimates as well at a tenth of the cost.
constexpr int kProbeSide = 512;
AutoExposure chooseAutoExposure(const engine::RendererConfig& config, const std::vector<engine::RenderPlugin*>& plugins,
                                const engine::Scene& scene, const engine::FrameCamera& camera);

// "auto exposure: EV100 12.34 (exposure 1.65e-05: log-average luminance 1.35e+04 of 12345
// pixels to middle grey 0.18)", or why nothing was measured.
std::string describe(const AutoExposure& chosen);

} // namespace tools
