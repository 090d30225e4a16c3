#include "OptionValues.h"

#include "engine/config/EngineConfig.h"
#include "engine/util/Error.h"
#include "engine/util/FormatNumber.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cerrno>
#include <cstdlib>
#include <stdexcept>

namespace tools {

namespace {

std::string joined(const std::vector<std::string>& items) {
    std::string text;
    for (const std::string& item : items) text += (text.empty() ? "" : ",") + item;
    return text;
}

} // namespace

int parseInteger(const std::string& flag, const std::string& text, int minimum, int maximum) {
    char* end = nullptr;
    errno = 0;
    const long value = std::strtol(text.c_str(), &end, 10);
    // strtol skips leading white space and takes a '+': a flag's value is digits only.
    const bool plainDigits = !text.empty() && (std::isdigit(static_cast<unsigned char>(text[0])) || text[0] == '-');
    if (!plainDigits || *end != '\0' || errno != 0 || value < minimum || value > maximum)
        throw std::invalid_argument(flag + ": \"" + text + "\" is not an integer in [" + std::to_string(minimum) +
                                    ", " + std::to_string(maximum) + "]");
    return static_cast<int>(value);
}

double parseNumber(const std::string& flag, const std::string& text, double minimum, double maximum) {
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(text.c_str(), &end);
    // strtod also takes white space, '+', hex, "inf" and "nan": a flag's value is a plain number.
    const bool plain = !text.empty() && (std::isdigit(static_cast<unsigned char>(text[0])) || text[0] == '-' ||
                                         text[0] == '.') &&
                       text.find_first_of("xXnN") == std::string::npos;
    if (!plain || *end != '\0' || errno != 0 || !(value >= minimum && value <= maximum))
        throw std::invalid_argument(flag + ": \"" + text + "\" is not a number in [" + engine::formatNumber(minimum) +
                                    ", " + engine::formatNumber(maximum) + "]");
    return value;
}

double parsePositiveNumber(const std::string& flag, const std::string& text, double maximum) {
    const double value = parseNumber(flag, text, 0.0, maximum);
    if (value <= 0.0)
        throw std::invalid_argument(flag + ": \"" + text + "\" is not a number in (0, " +
                                    engine::formatNumber(maximum) + "]");
    return value;
}

std::vector<std::string> parseList(const std::string& flag, const std::string& text) {
    std::vector<std::string> items;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (item.empty())
            throw std::invalid_argument(flag + ": empty item in \"" + text + "\" (items are separated by single commas)");
        if (std::find(items.begin(), items.end(), item) != items.end())
            throw std::invalid_argument(flag + ": \"" + item + "\" is listed twice in \"" + text + "\"");
        items.push_back(std::move(item));
        if (comma == std::string::npos) return items;
        start = comma + 1;
    }
}

std::vector<std::string> parseNames(const std::string& flag, const std::string& text,
                                    const std::vector<std::string>& known) {
    std::vector<std::string> items = parseList(flag, text);
    for (const std::string& item : items)
        if (std::find(known.begin(), known.end(), item) == known.end())
            throw std::invalid_argument(flag + ": unknown value \"" + item + "\" (known: " + joined(known) + ")");
    return items;
}

std::vector<int> parseIntegerList(const std::string& flag, const std::string& text, int minimum, int maximum) {
    std::vector<int> values;
    for (const std::string& item : parseList(flag, text)) values.push_back(parseInteger(flag, item, minimum, maximum));
    return values;
}

std::vector<double> parseNumberList(const std::string& flag, const std::string& text, double minimum, double maximum) {
    std::vector<double> values;
    for (const std::string& item : parseList(flag, text)) values.push_back(parseNumber(flag, item, minimum, maximum));
    return values;
}

Shard parseShard(const std::string& flag, const std::string& text) {
    const auto slash = text.find('/');
    if (slash == std::string::npos) throw std::invalid_argument(flag + ": \"" + text + "\" must be K/N");
    Shard shard;
    shard.count = parseInteger(flag, text.substr(slash + 1), 1, 10000);
    shard.index = parseInteger(flag, text.substr(0, slash), 1, shard.count);
    return shard;
}

std::pair<std::string, std::string> parseAssignment(const std::string& flag, const std::string& text) {
    const auto equals = text.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == text.size())
        throw std::invalid_argument(flag + ": \"" + text + "\" must be NAME=VALUE");
    return {text.substr(0, equals), text.substr(equals + 1)};
}

engine::Light::Type parseLightType(const std::string& flag, const std::string& text) {
    if (text == "spot") return engine::Light::Type::Spot;
    if (text == "point") return engine::Light::Type::Point;
    if (text == "directional") return engine::Light::Type::Directional;
    throw std::invalid_argument(flag + ": \"" + text + "\" is not spot, point or directional");
}

std::string defaultConfigPath() {
    try {
        return engine::findDefaultEngineConfig().string();
    } catch (const engine::InputError& error) {
        throw std::invalid_argument(std::string("no --config given and ") + error.what());
    }
}

} // namespace tools
