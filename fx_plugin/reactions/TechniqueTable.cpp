#include "TechniqueTable.h"

#include <cassert>

namespace fx {

const std::vector<TechniqueRow>& techniqueTable() {
    // word, drawn as, stateless, scene depth, ray through a sphere, display name, drawn by,
    // a program per contrast power
    static const std::vector<TechniqueRow> rows = {
        {"hard", Technique::Hard, false, false, false, "hard sprites", DrawnBy::Billboards, false},
        {"soft", Technique::Soft, false, true, false, "soft particles (depth fade)", DrawnBy::Billboards, true},
        {"spherical", Technique::Spherical, false, true, true, "spherical billboards (ray length through a sphere)",
         DrawnBy::Billboards, false},
        {"stateless", Technique::Hard, true, false, false, "stateless particles (GPU-evaluated hard billboards)",
         DrawnBy::Stateless, false},
        {"mega", Technique::Mega, false, true, false, "mega-particles (blurred spheres as one volume)", DrawnBy::Mega,
         false},
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

const TechniqueRow& drawnRow(Technique reactionTechnique, bool stateless, Technique override) {
    return techniqueRow(override == Technique::FromReaction || stateless ? reactionTechnique : override, stateless);
}

uint32_t techniquesDrawnBy(DrawnBy renderer) {
    uint32_t mask = 0;
    for (const TechniqueRow& row : techniqueTable())
        if (!row.stateless && row.drawnBy == renderer) mask |= 1u << static_cast<uint32_t>(row.technique);
    return mask;
}

std::vector<std::string> techniqueWords() {
    std::vector<std::string> words;
    for (const TechniqueRow& row : techniqueTable()) words.push_back(row.word);
    return words;
}

}  // namespace fx
