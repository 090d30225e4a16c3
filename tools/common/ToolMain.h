#pragma once
// The shared main() of the engine's command-line tools (engine-render, engine-view,
// shadowmap-bench, shadowmap-stress): parse the options (a bad flag: one line, exit 1),
// --help and --version, then run with a GL context and a plugin host that outlive the error report.
//
// Order matters twice: an exception thrown by plugin code must be read before the plugin is
// unloaded (so the host lives outside the try), and destroying the plugins deletes their GL
// objects, which needs the context current (so the context is declared first, dies last).
#include "engine/context/GlContext.h"
#include "engine/plugin/PluginHost.h"
#include "engine/util/Version.h"

#include <cstdio>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string_view>

namespace tools {

struct ToolSession {
    std::unique_ptr<engine::GlContext> context;  // first: destroyed after the host
    engine::PluginHost host;
};

// parse(argc, argv) -> Options (throws std::invalid_argument), Options::help, and
// run(const Options&, ToolSession&) -> exit code (throws on bad input).
template <typename Parse, typename Run>
int toolMain(const char* name, const char* usage, int argc, char** argv, Parse parse, Run run) {
    // --version alone: the engine's version, whatever the tool's required flags.
    if (argc == 2 && std::string_view(argv[1]) == "--version") {
        std::printf("%s %s\n", name, engine::version());
        return 0;
    }
    decltype(parse(argc, argv)) options;
    try {
        options = parse(argc, argv);
    } catch (const std::invalid_argument& error) {
        std::fprintf(stderr, "%s: %s (see --help)\n", name, error.what());
        return 1;
    }
    if (options.help) {
        std::fputs(usage, stdout);
        return 0;
    }
    ToolSession session;
    try {
        return run(options, session);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "%s: %s\n", name, error.what());
        return 1;
    }
}

} // namespace tools
