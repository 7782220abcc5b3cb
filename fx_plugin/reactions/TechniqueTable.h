#pragma once
// The technique vocabulary of reaction files in one table: a row per `render.technique` word.
// The loader (ReactionSchema.cpp), the editor schema and reactionValue (ReactionKeyTable.cpp),
// techniqueName() and the plugin's reaction stats all read it; tests/panel/EditSessionTest.cpp
// walks every row from a file through the loader, the schema, reactionValue and a saved file.
// Adding a technique is adding a row here (and the renderer that draws it).
#include <string>
#include <vector>

#include "fx/Plugin.h"  // Technique

namespace fx {

struct TechniqueRow {
    const char* word;          ///< spelling in a reaction file: `render.technique: soft`
    Technique technique;       ///< how it is drawn (stateless particles are hard billboards)
    bool stateless;            ///< birth records evaluated in the vertex shader, no CPU update
    bool needsSceneDepth;      ///< its fragments read the scene depth (fade, sphere depth)
    bool raySphere;            ///< a fragment is a ray through a sphere (box footprint at quarter res)
    const char* displayName;   ///< what menus, help and tables call it
};

/// Every technique, in the order the loader's messages list them (never changes).
const std::vector<TechniqueRow>& techniqueTable();
/// The row spelled `word` in a file, or null.
const TechniqueRow* findTechnique(const std::string& word);
/// The row a loaded reaction's render settings came from (`stateless` wins over `technique`);
/// `technique` is one of Hard, Soft, Spherical, Mega (asserted).
const TechniqueRow& techniqueRow(Technique technique, bool stateless);
/// The file words, table order.
std::vector<std::string> techniqueWords();

}  // namespace fx
