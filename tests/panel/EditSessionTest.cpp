// The panel's edit model on a running game: edits apply at once through the loader's
// validation, saves rewrite only the changed characters, undo/redo, revert, disk changes.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include "PanelTestUtil.h"
#include "panel/EditSession.h"

using namespace paneltest;
using cube::panel::EditSession;

namespace {

class EditSessionTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::string error;
        ASSERT_TRUE(game.Init(options(copy.dir()), &error)) << error;
        plugin = game.specialFX().plugin();
        ASSERT_NE(plugin, nullptr);
        session = std::make_unique<EditSession>(*plugin);
        ASSERT_TRUE(session->open(&error)) << error;
        burnout = reactionIndex(*plugin, "burnout_smoke");
        ASSERT_GE(burnout, 0);
        burnoutFile = copy.file("burnout_smoke.yaml");
        original = readFile(burnoutFile);
    }
    std::string value(const std::string& key) { return plugin->reactionValue(burnout, key); }

    ReactionCopy copy;
    cube::Game game;
    fx::Plugin* plugin = nullptr;
    std::unique_ptr<EditSession> session;
    int burnout = -1;
    std::string burnoutFile, original;
};


TEST_F(EditSessionTest, AnEditGoesLiveAtOnceAndTheSavedDiffIsOnlyThatScalar) {
    std::string error;
    ASSERT_TRUE(session->set(burnout, "particle.drag", "2.5", &error)) << error;
    EXPECT_EQ(value("particle.drag"), "2.5");  // the running plugin, before any save
    EXPECT_EQ(readFile(burnoutFile), original) << "nothing is written before Save";

    const int doc = session->documentOf(burnout);
    ASSERT_TRUE(session->save(doc, &error)) << error;
    const std::vector<std::string> before = lines(original), after = lines(readFile(burnoutFile));
    ASSERT_EQ(before.size(), after.size());
    int changed = 0;
    for (size_t i = 0; i < before.size(); ++i) {
        if (before[i] == after[i]) continue;
        ++changed;
        // Only the number: key, spacing and the line's comment are the same characters.
        std::string expected = before[i];
        expected.replace(expected.find("1.2"), 3, "2.5");
        EXPECT_EQ(after[i], expected);
    }
    EXPECT_EQ(changed, 1);
    EXPECT_FALSE(session->documents()[size_t(doc)].dirty());
}

TEST_F(EditSessionTest, TheSavedFileLoadsBackToTheSameValues) {
    std::string error;
    ASSERT_TRUE(session->set(burnout, "particle.lifetime[1]", "6.5", &error)) << error;
    ASSERT_TRUE(session->set(burnout, "particle.colour_ramp[1].rgba[3]", "0.5", &error)) << error;
    ASSERT_TRUE(session->set(burnout, "render.technique", "spherical", &error)) << error;
    ASSERT_TRUE(session->set(burnout, "trigger.surfaces", "[asphalt, kerb, grass]", &error)) << error;
    ASSERT_TRUE(session->save(session->documentOf(burnout), &error)) << error;

    cube::Game fresh;
    ASSERT_TRUE(fresh.Init(options(copy.dir()), &error)) << error;
    fx::Plugin& reloaded = *fresh.specialFX().plugin();
    const int index = reactionIndex(reloaded, "burnout_smoke");
    ASSERT_GE(index, 0);
    for (const fx::ReactionKeyInfo& key : plugin->reactionSchema()) {
        EXPECT_EQ(reloaded.reactionValue(index, key.key), value(key.key)) << key.key;
    }
    EXPECT_EQ(value("particle.lifetime"), "[3, 6.5]");
    EXPECT_EQ(value("render.technique"), "spherical");
}

TEST_F(EditSessionTest, AnOutOfRangeValueIsRefusedWithTheSchemasMessageAndChangesNothing) {
    const int running = plugin->reactionCount();  // every shipped reaction (recipes: one per layer)
    std::string error;
    const std::string text = session->documents()[size_t(session->documentOf(burnout))].text;
    EXPECT_FALSE(session->set(burnout, "particle.size_variation", "5", &error));
    EXPECT_NE(error.find("error[OutOfRange]"), std::string::npos) << error;
    EXPECT_NE(error.find("particle.size_variation: expected a number in [0, 0.9], got '5'"), std::string::npos) << error;
    EXPECT_NE(error.find("burnout_smoke.yaml:"), std::string::npos) << error;
    EXPECT_EQ(value("particle.size_variation"), "0.25");
    EXPECT_EQ(session->documents()[size_t(session->documentOf(burnout))].text, text);
    EXPECT_FALSE(session->canUndo());
    // A cross-key rule refuses too: fade_in + fade_out <= 1 (fade_out is 0.55).
    EXPECT_FALSE(session->set(burnout, "particle.fade_in", "0.6", &error));
    EXPECT_NE(error.find("fade_in + fade_out <= 1"), std::string::npos) << error;
    EXPECT_EQ(plugin->reactionCount(), running);
}

TEST_F(EditSessionTest, UndoAndRedoWalkTheEditsAndAGroupIsOneStep) {
    std::string error;
    // A drag: three values in one group are one undo step.
    for (const char* v : {"1.3", "1.4", "1.5"}) ASSERT_TRUE(session->set(burnout, "particle.drag", v, &error, "drag"));
    session->endGroup();
    ASSERT_TRUE(session->set(burnout, "emission.rate", "120", &error)) << error;
    ASSERT_TRUE(session->undo(&error)) << error;
    EXPECT_EQ(value("emission.rate"), "90");
    EXPECT_EQ(value("particle.drag"), "1.5");
    ASSERT_TRUE(session->undo(&error)) << error;
    EXPECT_EQ(value("particle.drag"), "1.2");
    EXPECT_FALSE(session->canUndo());
    EXPECT_EQ(session->documents()[size_t(session->documentOf(burnout))].text, original);
    ASSERT_TRUE(session->redo(&error)) << error;
    EXPECT_EQ(value("particle.drag"), "1.5");
    ASSERT_TRUE(session->redo(&error)) << error;
    EXPECT_EQ(value("emission.rate"), "120");
    EXPECT_FALSE(session->canRedo());
}

TEST_F(EditSessionTest, AKeyTheFileLeavesOutIsAddedOnItsOwnLine) {
    // A file that relies on defaults: no particle.spin and no render section.
    const std::string path = copy.file("burnout_smoke.yaml");
    std::string text = original;
    text.erase(text.find("      spin: [-0.5, 0.5]\n"), std::string("      spin: [-0.5, 0.5]\n").size());
    text.erase(text.find("    render:\n"));
    writeFile(path, text);
    std::string error;
    ASSERT_TRUE(game.specialFX().plugin()->loadReactions(copy.dir(), nullptr));
    ASSERT_TRUE(session->open(&error)) << error;
    EXPECT_EQ(value("particle.spin"), "[-0.6, 0.6]");  // the default
    ASSERT_TRUE(session->set(burnout, "particle.spin", "[-1, 1]", &error)) << error;
    ASSERT_TRUE(session->set(burnout, "render.softness", "0.9", &error)) << error;
    EXPECT_EQ(value("particle.spin"), "[-1, 1]");
    EXPECT_EQ(value("render.softness"), "0.9");
    const std::string edited = session->documents()[size_t(session->documentOf(burnout))].text;
    EXPECT_NE(edited.find("      atlas: [0, 4]\n      spin: [-1, 1]\n"), std::string::npos) << edited;
    EXPECT_NE(edited.find("    render: {softness: 0.9}\n"), std::string::npos) << edited;
    // Every original line is still there, in order.
    const std::vector<std::string> a = lines(text), b = lines(edited);
    size_t j = 0;
    for (const std::string& l : b) j += j < a.size() && l == a[j];
    EXPECT_EQ(j, a.size());
}

TEST_F(EditSessionTest, ColourRampStopsAreCopiedAndRemovedAsWholeLines) {
    std::string error;
    ASSERT_TRUE(session->duplicateStop(burnout, 1, &error)) << error;
    EXPECT_EQ(value("particle.colour_ramp"),
              "[{t: 0, rgba: [0.93, 0.93, 0.92, 0.85]}, {t: 0.35, rgba: [0.86, 0.86, 0.85, 0.7]}, "
              "{t: 0.35, rgba: [0.86, 0.86, 0.85, 0.7]}, {t: 1, rgba: [0.78, 0.78, 0.79, 0.45]}]");
    ASSERT_TRUE(session->removeStop(burnout, 2, &error)) << error;
    ASSERT_TRUE(session->removeStop(burnout, 1, &error)) << error;
    EXPECT_EQ(value("particle.colour_ramp"),
              "[{t: 0, rgba: [0.93, 0.93, 0.92, 0.85]}, {t: 1, rgba: [0.78, 0.78, 0.79, 0.45]}]");
    ASSERT_TRUE(session->undo(&error));
    ASSERT_TRUE(session->undo(&error));
    ASSERT_TRUE(session->undo(&error));
    EXPECT_EQ(session->documents()[size_t(session->documentOf(burnout))].text, original);
}

TEST_F(EditSessionTest, AFileChangedOnDiskWhileEditedAsksAndEitherAnswerHolds) {
    std::string error;
    ASSERT_TRUE(session->set(burnout, "particle.drag", "2.5", &error)) << error;
    std::string disk = original;
    disk.replace(disk.find("rate: 90"), 8, "rate: 70");
    writeFile(burnoutFile, disk);
    EXPECT_TRUE(session->checkDisk(&error));
    const int doc = session->documentOf(burnout);
    EXPECT_TRUE(session->documents()[size_t(doc)].conflict);
    EXPECT_EQ(value("particle.drag"), "2.5");  // nothing changes until the user answers
    EXPECT_EQ(value("emission.rate"), "90");

    ASSERT_TRUE(session->resolveConflict(doc, false, &error)) << error;  // keep mine
    EXPECT_FALSE(session->checkDisk(&error));                           // asked once
    EXPECT_EQ(value("particle.drag"), "2.5");
    EXPECT_TRUE(session->documents()[size_t(doc)].dirty());

    disk.replace(disk.find("rate: 70"), 8, "rate: 60");
    writeFile(burnoutFile, disk);
    EXPECT_TRUE(session->checkDisk(&error));
    ASSERT_TRUE(session->resolveConflict(doc, true, &error)) << error;  // reload
    EXPECT_EQ(value("particle.drag"), "1.2");
    EXPECT_EQ(value("emission.rate"), "60");
    EXPECT_FALSE(session->documents()[size_t(doc)].dirty());
}

TEST_F(EditSessionTest, RevertReloadsTheFileAndCanBeUndone) {
    std::string error;
    ASSERT_TRUE(session->set(burnout, "particle.drag", "2.5", &error)) << error;
    ASSERT_TRUE(session->revert(session->documentOf(burnout), &error)) << error;
    EXPECT_EQ(value("particle.drag"), "1.2");
    ASSERT_TRUE(session->undo(&error)) << error;
    EXPECT_EQ(value("particle.drag"), "2.5");
}

TEST_F(EditSessionTest, TheSchemaTableAgreesWithTheLoaderAtEveryBound) {
    // Each number key: past its bound is refused naming the range; at the bound it loads
    // (except where a cross-key rule of the shipped file forbids it).
    std::string error;
    for (const fx::ReactionKeyInfo& k : plugin->reactionSchema()) {
        if (k.kind != fx::ReactionKeyInfo::Kind::Number && k.kind != fx::ReactionKeyInfo::Kind::Integer) continue;
        const bool integer = k.kind == fx::ReactionKeyInfo::Kind::Integer;
        const double step = integer ? 1.0 : std::max(1e-3, (k.max - k.min) * 1e-3);
        for (double past : {k.min - step, k.max + step}) {
            char text[64];
            std::snprintf(text, sizeof text, integer ? "%.0f" : "%.9g", past);
            EXPECT_FALSE(session->set(burnout, k.key, text, &error)) << k.key << " = " << text;
            EXPECT_TRUE(error.find("OutOfRange") != std::string::npos || error.find("NegativeCount") != std::string::npos)
                << k.key << ": " << error;
        }
        const bool crossRule = k.key == "particle.fade_in" || k.key == "particle.fade_out" || k.key == "emission.burst";
        if (crossRule) continue;
        for (double bound : {k.min, k.max}) {
            char text[64];
            std::snprintf(text, sizeof text, integer ? "%.0f" : "%.9g", bound);
            EXPECT_TRUE(session->set(burnout, k.key, text, &error)) << k.key << " = " << text << ": " << error;
        }
        ASSERT_TRUE(session->revert(session->documentOf(burnout), &error)) << error;
    }
}

TEST_F(EditSessionTest, ASaveThatCannotWriteSaysWhereAndKeepsTheEdits) {
    std::string error;
    ASSERT_TRUE(session->set(burnout, "particle.drag", "2.5", &error)) << error;
    std::filesystem::remove_all(copy.dir());  // the folder is gone
    EXPECT_FALSE(session->save(session->documentOf(burnout), &error));
    EXPECT_NE(error.find("burnout_smoke.yaml: cannot write"), std::string::npos) << error;
    EXPECT_TRUE(session->documents()[size_t(session->documentOf(burnout))].dirty());
    EXPECT_EQ(value("particle.drag"), "2.5");
}

// The shipped files plus one stateless reaction of its own (the shipped ones are layers, which
// the edit session does not edit): burnout_smoke takes every enum word but `stateless`, which
// the loader allows only with additive blending and no turbulence or vortex.
class EnumWordTest : public EditSessionTest {
protected:
    void SetUp() override {
        writeFile(copy.file("stateless_sparks.yaml"),
                  "reactions:\n"
                  "  - name: stateless_sparks\n"
                  "    type: collision_burst\n"
                  "    emission: {burst: 64, capacity: 256}\n"
                  "    render:\n"
                  "      technique: stateless\n"
                  "      blend: additive\n");
        EditSessionTest::SetUp();
    }
    static std::string hostOf(const std::string& key, const std::string& word) {
        return key == "render.technique" && word == "stateless" ? "stateless_sparks" : "burnout_smoke";
    }
};

// The words an InvalidEnum message lists: "... expected one of a|b|c, got 'x'".
std::vector<std::string> wordsInMessage(const std::string& error) {
    const std::string from = "expected one of ";
    const size_t begin = error.find(from);
    if (begin == std::string::npos) return {};
    const size_t end = error.find(", got", begin);
    std::vector<std::string> words;
    std::string list = error.substr(begin + from.size(), end - begin - from.size()) + "|";
    for (size_t at = 0, bar; (bar = list.find('|', at)) != std::string::npos; at = bar + 1) words.push_back(list.substr(at, bar - at));
    return words;
}

// Both directions: every word the schema offers loads, and the loader accepts no word the
// schema leaves out (its refusal lists exactly the schema's words, in the schema's order).
// Before the technique table the schema left out `stateless` (and the types collision_scrape
// and on_demand) although the loader took them.
TEST_F(EnumWordTest, TheSchemaTablesWordsAreTheLoadersWords) {
    std::string error;
    int keys = 0;
    for (const fx::ReactionKeyInfo& k : plugin->reactionSchema()) {
        if (k.kind != fx::ReactionKeyInfo::Kind::Choice && k.kind != fx::ReactionKeyInfo::Kind::ChoiceList) continue;
        ++keys;
        ASSERT_FALSE(k.choices.empty()) << k.key;
        const bool list = k.kind == fx::ReactionKeyInfo::Kind::ChoiceList;
        for (const std::string& word : k.choices) {
            const int host = reactionIndex(*plugin, hostOf(k.key, word));
            ASSERT_GE(host, 0) << hostOf(k.key, word);
            EXPECT_TRUE(session->set(host, k.key, list ? "[" + word + "]" : word, &error)) << k.key << " = " << word << ": " << error;
            ASSERT_TRUE(session->revert(session->documentOf(host), &error)) << error;
        }
        EXPECT_FALSE(session->set(burnout, k.key, list ? "[not_a_word]" : "not_a_word", &error)) << k.key;
        EXPECT_NE(error.find("error[InvalidEnum]"), std::string::npos) << k.key << ": " << error;
        EXPECT_EQ(wordsInMessage(error), k.choices) << k.key << ": the loader's words are not the schema's: " << error;
        ASSERT_TRUE(session->revert(session->documentOf(burnout), &error)) << error;
    }
    EXPECT_EQ(keys, 5) << "type, trigger.surfaces, trigger.wheels, render.technique, render.blend";
}

// Every enum word from a file through the loader, reactionValue, a saved file and a fresh load:
// the running value reads back the word that was written (a stateless reaction read `hard`).
TEST_F(EnumWordTest, EveryEnumWordRoundTripsThroughTheLoaderReactionValueAndASavedFile) {
    std::string error;
    for (const fx::ReactionKeyInfo& k : plugin->reactionSchema()) {
        if (k.kind != fx::ReactionKeyInfo::Kind::Choice && k.kind != fx::ReactionKeyInfo::Kind::ChoiceList) continue;
        const bool list = k.kind == fx::ReactionKeyInfo::Kind::ChoiceList;
        const std::string before = value(k.key);
        for (const std::string& word : k.choices) {
            const std::string name = hostOf(k.key, word), text = list ? "[" + word + "]" : word;
            const int host = reactionIndex(*plugin, name);
            ASSERT_GE(host, 0) << name;
            ASSERT_TRUE(session->set(host, k.key, text, &error)) << k.key << " = " << word << ": " << error;
            EXPECT_EQ(plugin->reactionValue(host, k.key), text) << k.key;
            const int doc = session->documentOf(host);
            ASSERT_TRUE(session->save(doc, &error)) << error;
            EXPECT_NE(readFile(session->documents()[size_t(doc)].path).find(k.key.substr(k.key.rfind('.') + 1) + ": " + text),
                      std::string::npos) << k.key << " = " << word << " is in the saved file";

            cube::Game fresh;
            ASSERT_TRUE(fresh.Init(options(copy.dir()), &error)) << error;
            fx::Plugin& reloaded = *fresh.specialFX().plugin();
            const int index = reactionIndex(reloaded, name);
            ASSERT_GE(index, 0) << name;
            EXPECT_EQ(reloaded.reactionValue(index, k.key), text) << k.key << " after a save and a fresh load";
        }
        ASSERT_TRUE(session->set(burnout, k.key, before, &error)) << error;  // the next key starts from the shipped value
    }
}

// reactions/README.md's key tables list each enum's words as the schema does, in its order.
TEST_F(EditSessionTest, TheReadmeListsEachEnumsWordsAsTheSchemaDoes) {
    const std::vector<std::string> readme = lines(readFile(cube::paths::reactions() + "/README.md"));
    for (const fx::ReactionKeyInfo& k : plugin->reactionSchema()) {
        if (k.kind != fx::ReactionKeyInfo::Kind::Choice && k.kind != fx::ReactionKeyInfo::Kind::ChoiceList) continue;
        const std::string row = "| `" + k.key.substr(k.key.rfind('.') + 1) + "` |";
        auto line = std::find_if(readme.begin(), readme.end(), [&](const std::string& l) {
            return l.rfind(row, 0) == 0 && l.find("enum") != std::string::npos;
        });
        ASSERT_NE(line, readme.end()) << k.key << ": no enum row in reactions/README.md";
        std::vector<std::string> cells;  // | key | type | default | unit | range | meaning |
        for (size_t at = 0, bar; (bar = line->find('|', at)) != std::string::npos; at = bar + 1) cells.push_back(line->substr(at, bar - at));
        ASSERT_GE(cells.size(), 6u) << *line;
        std::vector<std::string> words;
        const std::string& range = cells[5];
        for (size_t open = range.find('`'); open != std::string::npos; open = range.find('`', range.find('`', open + 1) + 1)) {
            words.push_back(range.substr(open + 1, range.find('`', open + 1) - open - 1));
        }
        EXPECT_EQ(words, k.choices) << k.key << ": " << *line;
    }
}

// The shipped stateless sparks (barrier_scrape.yaml) read `stateless` in the panel, not `hard`.
TEST_F(EditSessionTest, AStatelessReactionReadsStateless) {
    const int sparks = reactionIndex(*plugin, "barrier_scrape.sparks");
    ASSERT_GE(sparks, 0);
    EXPECT_EQ(plugin->reactionValue(sparks, "render.technique"), "stateless");
    EXPECT_EQ(value("render.technique"), "soft");
}

TEST_F(EditSessionTest, HotReloadOfAnotherFileKeepsTheEditedText) {
    // fx::Plugin::loadReactionsFromText: the edited text stands in for its file in later reloads.
    std::string error;
    ASSERT_TRUE(session->set(burnout, "particle.drag", "2.5", &error)) << error;
    const std::string dust = copy.file("offtrack_dust.yaml");
    std::string text = readFile(dust);
    text.replace(text.find("rate: 50"), 8, "rate: 55");
    writeFile(dust, text);
    bool reloaded = false;
    for (int i = 0; i < 50 && !reloaded; ++i) {  // the library looks at most every 0.1 s
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        reloaded = plugin->pollHotReload(nullptr);
    }
    ASSERT_TRUE(reloaded);
    EXPECT_EQ(plugin->reactionValue(reactionIndex(*plugin, "offtrack_dust"), "emission.rate"), "55");
    EXPECT_EQ(value("particle.drag"), "2.5") << "the unsaved edit survived the reload";
    // A text for a file outside the set is refused by name.
    fx::Diagnostics diags;
    EXPECT_FALSE(plugin->loadReactionsFromText(copy.dir() + "/other.yaml", "reactions: []\n", &diags));
    ASSERT_FALSE(diags.empty());
    EXPECT_EQ(diags.front().code, fx::ErrorCode::FileNotFound);
}

}  // namespace
