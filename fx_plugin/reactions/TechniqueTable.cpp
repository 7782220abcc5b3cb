#include "TechniqueTable.h"

#include <cassert>

namespace fx {

const std::vector<TechniqueRow>& techniqueTable() {
    // word, drawn as, stateless, scene depth, ray through a sphere, display name
    static const std::vector<TechniqueRow> rows = {
        {"hard", Technique::Hard, false, false, false, "hard sprites"},
        {"soft", Technique::Soft, false, true, false, "soft particles (depth fade)"},
        {"spherical", Technique::Spherical, false, true, true, "spherical billboards (ray length through a sphere)"},
        {"stateless", Technique::Hard, true, false, false, "stateless particles (GPU-evaluated hard billboards)"},
        {"mega", Technique::Mega, false, true, false, "mega-particles (blurred spheres as one volume)"},
    };
    return rows;
}

const TechniqueRow* findTechnique(const std::string& word) {
    for (const TechniqueRow& row : techniqueTable())
        if (word == row.word) return &row;
    return nullptr;
}

const TechniqueRow& techniqueRow(Technique technique, bool stateless) {
    for (const TechniqueRow& row : techniqueTable())
        if (row.stateless == stateless && (stateless || row.technique == technique)) return row;
    assert(!"techniqueRow: FromReaction or an out-of-range technique");
    return techniqueTable().front();
}

std::vector<std::string> techniqueWords() {
    std::vector<std::string> words;
    for (const TechniqueRow& row : techniqueTable()) words.push_back(row.word);
    return words;
}

}  // namespace fx
