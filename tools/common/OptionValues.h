#pragma once
// The values the tools' flags take, parsed one way for every tool (engine-render, engine-view,
// shadowmap-bench, shadowmap-stress). Each parser names the flag in its error, thrown as
// std::invalid_argument (one line, which toolMain prints), so every tool words a bad value
// alike: `--width: "0" is not an integer in [1, 16384]`.
#include "engine/scene/Scene.h"

#include <string>
#include <utility>
#include <vector>

namespace tools {

// The image size engine-render renders and engine-view opens when none is given. shadowmap-tune
// measures at it too: a shadow setting's error depends on the size it is seen at (a coarse map
// scores well on a small image and shows its texels on a large one), so the tuner's default
// choice holds for the picture the user will look at.
constexpr int kDefaultImageWidth = 1280, kDefaultImageHeight = 720;

// A decimal integer in [minimum, maximum]: no sign games, no trailing text, no overflow.
int parseInteger(const std::string& flag, const std::string& text, int minimum, int maximum);

// A finite decimal number in [minimum, maximum] ("0.5", "2", "1e-3"): no trailing text, no
// inf or nan.
double parseNumber(const std::string& flag, const std::string& text, double minimum, double maximum);
// The same in (0, maximum].
double parsePositiveNumber(const std::string& flag, const std::string& text, double maximum);

// A comma-separated list: "a,b,c". One rule for every list flag: an empty item (",a", "a,,b",
// "a,", "") and an item listed twice are errors naming the flag and the item.
std::vector<std::string> parseList(const std::string& flag, const std::string& text);

// parseList whose every item must be one of `known` (the error lists them).
std::vector<std::string> parseNames(const std::string& flag, const std::string& text,
                                    const std::vector<std::string>& known);

// parseList of integers, each in [minimum, maximum].
std::vector<int> parseIntegerList(const std::string& flag, const std::string& text, int minimum, int maximum);

// parseList of numbers (parseNumber), each in [minimum, maximum].
std::vector<double> parseNumberList(const std::string& flag, const std::string& text, double minimum, double maximum);

// --shard K/N of the sweeping tools (shadowmap-bench, shadowmap-tune): shard K of N, 1-based,
// 1 <= K <= N <= 10000.
struct Shard {
    int index = 1, count = 1;
};
Shard parseShard(const std::string& flag, const std::string& text);

// NAME=VALUE with both sides non-empty (the first '=' splits: VALUE may hold more).
std::pair<std::string, std::string> parseAssignment(const std::string& flag, const std::string& text);

// --key-light's light types: spot, point or directional.
engine::Light::Type parseLightType(const std::string& flag, const std::string& text);

// --config's value when the flag is absent: engine::findDefaultEngineConfig (a checkout's
// content/engine.json, else the installed one), its "none found" error as a flag error.
std::string defaultConfigPath();

} // namespace tools
