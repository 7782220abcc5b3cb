// libFuzzer target: the reaction loader (YAML parse + schema validation) on arbitrary bytes.
// Any crash, hang, sanitizer report or escaped exception is a bug; diagnostics are fine.
#include <cstddef>
#include <cstdint>
#include <string>

#include "reactions/ReactionLoader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    fx::ReactionSet set;
    fx::Diagnostics diags;
    const bool ok = fx::loadReactionText(text, "fuzz.yaml", &set, &diags);
    // The loader's contract: success means no diagnostics, failure means at least one.
    if (ok != diags.empty()) __builtin_trap();
    for (const fx::Diagnostic& d : diags) (void)d.str();
    return 0;
}
