// libFuzzer target: the legacy smoke loader on arbitrary text. It must never crash, throw or
// hang, and a text it accepts must hold values inside the documented ranges.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "scene/LegacySmokeDesc.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::vector<cube::LegacySmokeDesc> out;
    fx::Diagnostics diags;
    if (cube::loadLegacySmokeText(text, "fuzz.yaml", &out, &diags)) {
        if (!diags.empty()) std::abort();  // success reports nothing
        for (const cube::LegacySmokeDesc& d : out) {
            if (d.name.empty() || d.capacity < 1 || d.capacity > 100000) std::abort();
            if (!(d.alpha >= 0.0f && d.alpha <= 1.0f)) std::abort();
        }
    } else if (diags.empty()) {
        std::abort();  // every failure says why
    }
    return 0;
}
