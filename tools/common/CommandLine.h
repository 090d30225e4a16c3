#pragma once
// The flag loop of the tools' option parsers (engine-render, engine-view, shadowmap-bench):
// every argument is a "--flag VALUE" pair or a value-less switch, and -h/--help stops parsing.
// Each tool keeps its own flags, value checks and required flags; the loop owns the errors
// they share (thrown as std::invalid_argument, which toolMain reports as one line).
#include <algorithm>
#include <functional>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>

namespace tools {

// Called once per flag; value is empty for a switch. Returns false for a flag the tool does
// not know.
using FlagHandler = std::function<bool(const std::string& flag, const std::string& value)>;

// Walks argv[1..] and hands every flag to handleFlag. Returns true when -h or --help was
// given: parsing stops there, so the caller returns at once (no required-flag checks).
// Every flag not listed in switches takes the next argument as its value, whatever it looks
// like. A flag the tool does not know is "unknown option --typo" wherever it stands, the
// last argument included; a known one without its value is "--flag: missing value".
inline bool parseFlags(int argc, char** argv, std::initializer_list<std::string_view> switches,
                       const FlagHandler& handleFlag) {
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "--help" || flag == "-h") return true;
        if (flag.rfind("--", 0) != 0) throw std::invalid_argument("unexpected argument \"" + flag + "\"");
        const bool isSwitch = std::find(switches.begin(), switches.end(), flag) != switches.end();
        if (!isSwitch && i + 1 >= argc) {
            // Known or a typo? Only the handler knows: ask it with an empty value (what it
            // sets or throws no longer matters, parsing fails either way).
            bool known = true;
            try {
                known = handleFlag(flag, std::string());
            } catch (const std::exception&) {
            }
            throw std::invalid_argument(known ? flag + ": missing value" : "unknown option " + flag);
        }
        const std::string value = isSwitch ? std::string() : argv[++i];
        if (!handleFlag(flag, value)) throw std::invalid_argument("unknown option " + flag);
    }
    return false;
}

// For a tool whose flags all take a value.
inline bool parseFlags(int argc, char** argv, const FlagHandler& handleFlag) {
    return parseFlags(argc, argv, {}, handleFlag);
}

} // namespace tools
