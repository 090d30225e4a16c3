#include "GltfJsonDocument.h"

#include <cstring>

namespace engine::gltf {

void checkJsonNesting(const LoadContext& context, std::string_view text) {
    int depth = 0;
    bool inString = false;
    bool escaped = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') inString = false;
            continue;
        }
        switch (c) {
        case '"': inString = true; break;
        case '{':
        case '[':
            if (++depth > context.options.maxJsonDepth)
                context.fail("JSON", "nesting deeper than " + std::to_string(context.options.maxJsonDepth) +
                                         " levels (at byte " + std::to_string(i) + ")");
            break;
        case '}':
        case ']':
            // Unbalanced closers are the parser's to report; only depth matters here.
            if (depth > 0) --depth;
            break;
        default: break;
        }
    }
}

nlohmann::json parseJsonDocument(const LoadContext& context, std::string_view text) {
    try {
        nlohmann::json document = nlohmann::json::parse(text.begin(), text.end());
        if (!document.is_object()) context.fail("JSON", "the top level is not an object");
        return document;
    } catch (const nlohmann::json::exception& error) {
        // parse_error for bad syntax, out_of_range for a number beyond double (1e400).
        // what() starts with "[json.exception.parse_error.101] "; the rest is the sentence.
        const char* message = error.what();
        if (const char* end = std::strstr(message, "] ")) message = end + 2;
        context.fail("JSON", message);
    }
}

} // namespace engine::gltf
