#pragma once
// The GL fixture of the truth tests: the engine's shared EGL test context, plus a pinned GL
// driver.
//
// Why the pin: at exit the context's destruction makes Mesa dlclose its DRI driver
// (swrast_dri.so on Debian 12). Memory the driver still references from its own globals then
// looks leaked to LeakSanitizer (128-240 bytes, with stack frames pointing into the unmapped
// driver, so no suppression can name them). Keeping the driver mapped (RTLD_NODELETE) keeps
// those references visible and the ASan build clean, while real leaks are still reported.
#include "../../../tests/gl/GlTestContext.h"

#include <dlfcn.h>
#include <link.h>

#include <cstring>
#include <string>
#include <vector>

namespace truth::test {

inline void pinGlDrivers() {
    static const bool pinned = [] {
        std::vector<std::string> drivers;
        dl_iterate_phdr(
            [](dl_phdr_info* info, std::size_t, void* out) {
                if (info->dlpi_name && std::strstr(info->dlpi_name, "_dri.so"))
                    static_cast<std::vector<std::string>*>(out)->push_back(info->dlpi_name);
                return 0;
            },
            &drivers);
        // dlopen outside the iteration (which holds the loader's lock); the handles are kept
        // on purpose: the point is never to unload.
        for (const std::string& driver : drivers)
            dlopen(driver.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
        return true;
    }();
    (void)pinned;
}

class TruthGlTest : public engine::test::GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();  // creates the context, which loads the driver
        pinGlDrivers();
    }
};

} // namespace truth::test
