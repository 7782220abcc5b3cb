// Spellings of the enum words of reaction files, one list per enum indexed by its value: the
// loader (parsing, messages), the editor schema (ReactionKeyTable) and reactionValue all read
// these lists, so a word the loader accepts is always a word the schema offers. Techniques have
// their own table (TechniqueTable.h): a technique word carries more than its enum value.
#include "reactions/ReactionDesc.h"

namespace fx {
namespace {

const char* wordOf(const std::vector<std::string>& words, int i) {
    return i >= 0 && size_t(i) < words.size() ? words[size_t(i)].c_str() : "?";
}

}  // namespace

const std::vector<std::string>& reactionTypeWords() {
    static const std::vector<std::string> words = {"wheel_smoke", "dust", "collision_burst", "collision_scrape", "on_demand"};
    return words;
}

const std::vector<std::string>& wheelSetWords() {
    static const std::vector<std::string> words = {"rear", "front", "all"};
    return words;
}

const std::vector<std::string>& blendModeWords() {
    static const std::vector<std::string> words = {"alpha", "premultiplied", "additive"};
    return words;
}

const std::vector<std::string>& surfaceWords() {
    static const std::vector<std::string> words = {"asphalt", "kerb", "grass", "gravel", "sand"};
    return words;
}

const char* reactionTypeName(ReactionType type) { return wordOf(reactionTypeWords(), int(type)); }
const char* wheelSetName(WheelSet wheels) { return wordOf(wheelSetWords(), int(wheels)); }
const char* blendModeName(BlendMode blend) { return wordOf(blendModeWords(), int(blend)); }
const char* surfaceName(Surface surface) { return wordOf(surfaceWords(), int(surface)); }

}  // namespace fx
