// The technique table's renderer column (TechniqueRow::drawnBy): every technique is drawn by
// exactly one renderer, and the override reaches every reaction but a stateless one.
#include <cstdint>

#include <gtest/gtest.h>

#include "../../fx_plugin/reactions/TechniqueTable.h"

namespace technique_table_test {
namespace {

uint32_t bit(fx::Technique t) { return 1u << static_cast<uint32_t>(t); }

TEST(TechniqueTable, EachPoolTechniqueIsDrawnByExactlyOneRenderer) {
    const uint32_t billboards = fx::techniquesDrawnBy(fx::DrawnBy::Billboards);
    const uint32_t mega = fx::techniquesDrawnBy(fx::DrawnBy::Mega);
    EXPECT_EQ(billboards, bit(fx::Technique::Hard) | bit(fx::Technique::Soft) | bit(fx::Technique::Spherical));
    EXPECT_EQ(mega, bit(fx::Technique::Mega));
    EXPECT_EQ(billboards & mega, 0u);
    // Stateless reactions have no pool: no pool technique is theirs.
    EXPECT_EQ(fx::techniquesDrawnBy(fx::DrawnBy::Stateless), 0u);
    EXPECT_EQ(fx::techniqueRow(fx::Technique::Hard, true).drawnBy, fx::DrawnBy::Stateless);
}

TEST(TechniqueTable, TheOverrideReachesEveryReactionButAStatelessOne) {
    using fx::Technique;
    EXPECT_EQ(&fx::drawnRow(Technique::Soft, false, Technique::FromReaction), &fx::techniqueRow(Technique::Soft, false));
    EXPECT_EQ(&fx::drawnRow(Technique::Soft, false, Technique::Mega), &fx::techniqueRow(Technique::Mega, false));
    EXPECT_EQ(fx::drawnRow(Technique::Hard, true, Technique::Mega).drawnBy, fx::DrawnBy::Stateless);
    // Only soft draws with a program per contrast power.
    for (const fx::TechniqueRow& row : fx::techniqueTable()) {
        EXPECT_EQ(row.powerPrograms, row.technique == Technique::Soft && !row.stateless) << row.word;
    }
}

}  // namespace
}  // namespace technique_table_test
