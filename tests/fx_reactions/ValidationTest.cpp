// One test per validation rule: each asserts the ErrorCode, the 1-based line (and column where
// it is unambiguous) and the dotted key, not the wording (the wording is checked only where the
// "expected ..., got ..." contract is the point).
#include <string>

#include <gtest/gtest.h>

#include "../../fx_plugin/reactions/ReactionLoader.h"
#include "ReactionTextTest.h"

// Named so that the test files of one unity translation unit keep their helpers apart.
namespace validation_test {
namespace {

using fx::ErrorCode;
using reactiontest::dump;
using reactiontest::expectDiagnostics;
using reactiontest::expectOnly;
using reactiontest::Loaded;

Loaded load(const std::string& text) { return reactiontest::loadText(text); }

// A valid reaction with one particle key replaced: line 5, value at column 13 for short keys.
std::string withParticleKey(const std::string& keyAndValue) {
    return "reactions:\n"
           "  - name: a\n"
           "    type: dust\n"
           "    particle:\n"
           "      " + keyAndValue + "\n";
}

TEST(Validation, MinimalReactionIsValidAndTakesTypeDefaults) {
    Loaded r = load("reactions:\n  - name: a\n    type: dust\n");
    ASSERT_TRUE(r.ok) << dump(r.diags);
    ASSERT_EQ(r.set.reactions.size(), 1u);
    const fx::ReactionDesc& d = r.set.reactions[0];
    EXPECT_EQ(d.trigger.wheels, fx::WheelSet::All);  // dust default, not the wheel_smoke one
    EXPECT_EQ(d.emission.capacity, fx::EmissionDesc{}.capacity);
    EXPECT_EQ(d.sourceLine, 2);
}

using reactiontest::Rejected;

class RejectedText : public ::testing::TestWithParam<Rejected> {};

TEST_P(RejectedText, IsTheOnlyDiagnostic) { reactiontest::expectRejected(GetParam()); }

// A dust reaction with one more section key `body` from line 4 on.
std::string dustWith(const std::string& body) { return "reactions:\n  - name: a\n    type: dust\n" + body; }

// One rule a row: code, line, column (0 where it is ambiguous), key, and what the message must name.
const Rejected kRejected[] = {
    {"UnknownKey", withParticleKey("dragg: 2"), ErrorCode::UnknownKey, 5, 7, "reactions[0].particle.dragg",
     "drag"},  // lists the real keys
    {"WrongTypeSaysWhatWasExpected", withParticleKey("drag: fast"), ErrorCode::WrongType, 5, 13,
     "reactions[0].particle.drag", "expected a number in [0, 1e+06], got 'fast'"},
    {"QuotedNumberIsTextNotANumber", withParticleKey("drag: \"1.5\""), ErrorCode::WrongType, 5, 13,
     "reactions[0].particle.drag"},
    {"MapWhereASectionWasExpectedIsWrongType", dustWith("    render: soft\n"), ErrorCode::WrongType, 4, 13,
     "reactions[0].render"},
    {"OutOfRange", "reactions:\n  - name: a\n    type: wheel_smoke\n    trigger:\n      slip_threshold: 1.5\n",
     ErrorCode::OutOfRange, 5, 23, "reactions[0].trigger.slip_threshold", "[0, 1]"},
    {"NaN", withParticleKey("drag: .nan"), ErrorCode::NotFinite, 5, 13, "reactions[0].particle.drag"},
    {"NaNCapitalised", withParticleKey("drag: .NaN"), ErrorCode::NotFinite, 5, 13, "reactions[0].particle.drag"},
    {"NegativeInf", withParticleKey("rise_speed: -.inf"), ErrorCode::NotFinite, 5, 19,
     "reactions[0].particle.rise_speed"},
    {"Inf", withParticleKey("drag: .Inf"), ErrorCode::NotFinite, 5, 13, "reactions[0].particle.drag"},
    {"NumberTooLargeForADoubleIsOutOfRange", withParticleKey("drag: 1e999"), ErrorCode::OutOfRange, 5, 13,
     "reactions[0].particle.drag"},
    {"NegativeCapacity", dustWith("    emission:\n      capacity: -5\n"), ErrorCode::NegativeCount, 5, 17,
     "reactions[0].emission.capacity", "-5"},
    // Capacity is bounded and integral.
    {"CapacityPastTheBound", dustWith("    emission: {capacity: 1000001}\n"), ErrorCode::OutOfRange, 4, 0,
     "reactions[0].emission.capacity"},
    {"CapacityPastAnyInteger", dustWith("    emission: {capacity: 99999999999999999999999}\n"),
     ErrorCode::OutOfRange, 4, 0, "reactions[0].emission.capacity"},
    {"ZeroCapacity", dustWith("    emission: {capacity: 0}\n"), ErrorCode::OutOfRange, 4, 0,
     "reactions[0].emission.capacity"},
    {"FractionalCapacity", dustWith("    emission: {capacity: 2.5}\n"), ErrorCode::WrongType, 4, 0,
     "reactions[0].emission.capacity"},
    {"InvalidEnum", dustWith("    render:\n      technique: fluffy\n"), ErrorCode::InvalidEnum, 5, 18,
     "reactions[0].render.technique", "hard|soft|spherical"},
    {"InvalidEnumInAListNamesTheEntry", dustWith("    trigger:\n      surfaces: [grass, mud]\n"),
     ErrorCode::InvalidEnum, 5, 25, "reactions[0].trigger.surfaces[1]"},
    {"InvalidType", "reactions:\n  - name: a\n    type: smoke\n", ErrorCode::InvalidEnum, 3, 11, "reactions[0].type"},
    {"MissingName", "reactions:\n  - type: dust\n    emission: {rate: 10}\n", ErrorCode::MissingKey, 2, 5,
     "reactions[0].name"},
    {"MissingType", "reactions:\n  - name: a\n", ErrorCode::MissingKey, 2, 5, "reactions[0].type"},
    {"InvalidName", "reactions:\n  - name: 'two words'\n    type: dust\n", ErrorCode::WrongType, 2, 11,
     "reactions[0].name"},
    {"DuplicateName", "reactions:\n  - name: a\n    type: dust\n  - name: a\n    type: wheel_smoke\n",
     ErrorCode::DuplicateName, 4, 11, "reactions[1].name", "line 2"},
    {"DuplicateKey", dustWith("    particle:\n      drag: 1\n      drag: 2\n"), ErrorCode::DuplicateKey, 6, 7,
     "reactions[0].particle.drag"},
    {"EmptyFile", "", ErrorCode::EmptyFile, 1, 1, ""},
    {"OnlyACommentIsAnEmptyFile", "# only a comment\n\n   \n", ErrorCode::EmptyFile, 1, 1, ""},
    // 16 levels of list where a number belongs: the bound is 16 levels in the whole file.
    {"TooDeepInsideTheSchema", withParticleKey("drag: [[[[[[[[[[[[[[[[1]]]]]]]]]]]]]]]]"), ErrorCode::TooDeep, 5,
     13, "reactions[0].particle.drag"},
    // A shallow wrong value at the same place is only a wrong type.
    {"ShallowListForANumberIsWrongType", withParticleKey("drag: [[1]]"), ErrorCode::WrongType, 5, 13,
     "reactions[0].particle.drag"},
    {"MalformedIndentationIsASyntaxError", "reactions:\n- name: a\n  type: dust\n    drag: 1\n",
     ErrorCode::SyntaxError, 4, 9, ""},
    {"BinaryGarbage", "reactions:\n  - name: a" + std::string("\x00\xff\xfe\x01garbage", 11),
     ErrorCode::SyntaxError, 2, 12, "", "0x00"},
    {"InvalidUtf8IsBinary", "reactions:\n  - name: a\xc3\x28\n", ErrorCode::SyntaxError, 2, 12, ""},
};
INSTANTIATE_TEST_SUITE_P(Validation, RejectedText, ::testing::ValuesIn(kRejected), reactiontest::rejectedName);

TEST(Validation, NegativeBurstAndAtlasCountAreNegativeCounts) {
    Loaded r = load(
        "reactions:\n"
        "  - name: a\n"
        "    type: collision_burst\n"
        "    emission: {burst: -1}\n"
        "    particle: {atlas: [0, -2]}\n");
    expectDiagnostics(r, {{ErrorCode::NegativeCount, "reactions[0].emission.burst"},
                          {ErrorCode::NegativeCount, "reactions[0].particle.atlas[1]", 5}});
}

TEST(Validation, TheLargestCapacityIsValid) {
    Loaded max = load("reactions:\n  - name: a\n    type: dust\n    emission: {capacity: 1000000}\n");
    EXPECT_TRUE(max.ok) << dump(max.diags);
}

TEST(Validation, MissingReactionsKey) {
    // The typo, and what it hides.
    expectDiagnostics(load("reaction: []\n"), {{ErrorCode::UnknownKey, "reaction"}, {ErrorCode::MissingKey, "reactions"}});
    Loaded r = load("{}\n");
    expectOnly(r, ErrorCode::MissingKey, 1, 0, "reactions");
}

TEST(Validation, TooDeepForTheParser) {
    // Far past yaml-cpp's own recursion guard: reported, not a stack overflow.
    std::string deep = "reactions: " + std::string(5000, '[') + std::string(5000, ']') + "\n";
    expectDiagnostics(load(deep), {{ErrorCode::TooDeep, nullptr, 1}});
}

TEST(Validation, TruncatedYaml) {
    Loaded r = load(
        "reactions:\n"
        "  - name: a\n"
        "    type: dust\n"
        "    particle: {drag: 1.0, lifetime: [1, 2");
    expectDiagnostics(r, {{ErrorCode::SyntaxError, "", 4}});
}

TEST(Validation, ValidUtf8AndAByteOrderMarkAreFine) {
    // Valid UTF-8 (in a comment) and a byte-order mark are fine.
    Loaded ok = load("\xEF\xBB\xBF# r\xC3\xA9" "action\nreactions: []\n");
    EXPECT_TRUE(ok.ok) << dump(ok.diags);
}

TEST(Validation, TwoDocumentsAreASyntaxError) {
    // Line 2: where the second document starts.
    expectDiagnostics(load("reactions: []\n---\nreactions: []\n"), {{ErrorCode::SyntaxError, nullptr, 2}});
}

TEST(Validation, StrayCommaAtDocumentLevelIsASyntaxError) {
    // yaml-cpp 0.7 yields empty documents forever here (YAML::LoadAll would eat all memory).
    expectDiagnostics(load("# comment\n, defaults\nreactions: []\n"), {{ErrorCode::SyntaxError, nullptr, 2, 1}});
}

TEST(Validation, CrossFieldRules) {
    Loaded r = load(
        "reactions:\n"
        "  - name: a\n"
        "    type: collision_burst\n"
        "    emission: {burst: 300, capacity: 200}\n"       // burst > capacity
        "    particle:\n"
        "      lifetime: [3, 1]\n"                           // min > max
        "      fade_in: 0.6\n"
        "      fade_out: 0.6\n"                              // sum > 1
        "      atlas: [2, 3]\n"                              // past frame 3
        "      colour_ramp:\n"
        "        - {t: 0.5, rgba: [1, 1, 1, 1]}\n"
        "        - {t: 0.2, rgba: [1, 1, 1, 1]}\n");         // t going back
    expectDiagnostics(r, {{ErrorCode::OutOfRange, "reactions[0].emission.burst"},
                          {ErrorCode::OutOfRange, "reactions[0].particle.lifetime", 6},
                          {ErrorCode::OutOfRange, "reactions[0].particle.fade_out", 8},
                          {ErrorCode::OutOfRange, "reactions[0].particle.atlas"},
                          {ErrorCode::OutOfRange, "reactions[0].particle.colour_ramp[1].t", 12}});
}

TEST(Validation, ColourRampShape) {
    Loaded r = load(
        "reactions:\n"
        "  - name: a\n"
        "    type: dust\n"
        "    particle:\n"
        "      colour_ramp:\n"
        "        - {t: 0, rgba: [1, 1, 1]}\n"
        "        - {rgba: [1, 1, 1, 2]}\n");
    expectDiagnostics(r, {{ErrorCode::OutOfRange, "reactions[0].particle.colour_ramp[0].rgba"},  // 3 channels, 4 expected
                          {ErrorCode::MissingKey, "reactions[0].particle.colour_ramp[1].t"},
                          {ErrorCode::OutOfRange, "reactions[0].particle.colour_ramp[1].rgba[3]"}});
}

TEST(Validation, ThreeErrorsReportThree) {
    Loaded r = load(
        "reactions:\n"
        "  - name: a\n"
        "    type: smoke\n"
        "    emission:\n"
        "      capacity: -1\n"
        "    particle:\n"
        "      drag: .inf\n");
    expectDiagnostics(r, {{ErrorCode::InvalidEnum, nullptr, 3},
                          {ErrorCode::NegativeCount, nullptr, 5},
                          {ErrorCode::NotFinite, nullptr, 7}});
}

TEST(Validation, ErrorsInSeveralReactionsAreAllReported) {
    Loaded r = load(
        "reactions:\n"
        "  - name: a\n"
        "    type: dust\n"
        "    emission: {rate: -1}\n"
        "  - name: b\n"
        "    type: dust\n"
        "    render: {blend: multiply}\n");
    expectDiagnostics(r, {{ErrorCode::OutOfRange, "reactions[0].emission.rate"},
                          {ErrorCode::InvalidEnum, "reactions[1].render.blend"}});
}

TEST(Validation, BadFileLeavesTheOutputUntouched) {
    fx::ReactionSet set;
    set.reactions.resize(1);
    set.reactions[0].name = "sentinel";
    set.files.push_back("earlier.yaml");
    fx::Diagnostics diags;
    EXPECT_FALSE(fx::loadReactionText(withParticleKey("drag: fast"), "bad.yaml", &set, &diags));
    ASSERT_EQ(set.reactions.size(), 1u);
    EXPECT_EQ(set.reactions[0].name, "sentinel");
    ASSERT_EQ(set.files.size(), 1u);
    EXPECT_EQ(set.files[0], "earlier.yaml");
    // A null diagnostics list is allowed.
    EXPECT_FALSE(fx::loadReactionText("reactions: 5", "bad.yaml", &set, nullptr));
    EXPECT_EQ(set.reactions[0].name, "sentinel");
}

TEST(Validation, TooManyReactionsAndTooMuchCapacity) {
    std::string many = "reactions:\n";
    for (int i = 0; i < fx::kMaxReactionsPerFile + 1; ++i) {
        many += "  - {name: r" + std::to_string(i) + ", type: dust}\n";
    }
    expectOnly(load(many), ErrorCode::OutOfRange, 2, 0, "reactions");

    std::string heavy = "reactions:\n";
    for (int i = 0; i < 5; ++i) {
        heavy += "  - {name: r" + std::to_string(i) + ", type: dust, emission: {capacity: 1000000}}\n";
    }
    expectOnly(load(heavy), ErrorCode::OutOfRange, 6, 0, "reactions[4].emission.capacity");
}

TEST(Validation, DiagnosticsPerFileAreCapped) {
    std::string text = "reactions:\n  - name: a\n    type: dust\n    particle:\n";
    for (int i = 0; i < 300; ++i) text += "      k" + std::to_string(i) + ": 1\n";
    Loaded r = load(text);
    EXPECT_FALSE(r.ok);
    ASSERT_EQ(r.diags.size(), fx::kMaxDiagnosticsPerFile + 1);
    EXPECT_EQ(r.diags.back().code, ErrorCode::TooManyErrors);
}

TEST(Validation, SelfReferencingAliasTerminates) {
    // yaml-cpp registers an anchor before its children, so this node contains itself.
    Loaded r = load("reactions: &a [*a]\n");
    EXPECT_FALSE(r.ok);
    ASSERT_FALSE(r.diags.empty());
    Loaded deep = load("reactions:\n  - name: a\n    type: dust\n    particle: {drag: &d [*d]}\n");
    expectDiagnostics(deep, {{ErrorCode::TooDeep}});
}

TEST(Validation, AliasExpansionIsNotExpanded) {
    // "Billion laughs": 9 levels of 10 aliases each would be 10^9 nodes if walked.
    std::string text = "l0: &l0 [x, x, x, x, x, x, x, x, x, x]\n";
    for (int i = 1; i < 10; ++i) {
        std::string p = "*l" + std::to_string(i - 1);
        text += "l" + std::to_string(i) + ": &l" + std::to_string(i) + " [" + p;
        for (int k = 1; k < 10; ++k) text += ", " + p;
        text += "]\n";
    }
    text += "reactions: [*l9]\n";
    Loaded r = load(text);
    EXPECT_FALSE(r.ok);
    EXPECT_FALSE(r.diags.empty());
}

TEST(Validation, DiagnosticStrFormat) {
    Loaded r = load(withParticleKey("drag: fast"));
    ASSERT_EQ(r.diags.size(), 1u);
    EXPECT_EQ(r.diags[0].str(),
              "test.yaml:5:13: error[WrongType] reactions[0].particle.drag: expected a number in "
              "[0, 1e+06], got 'fast'");
    EXPECT_STREQ(fx::errorCodeName(ErrorCode::NegativeCount), "NegativeCount");
}

}  // namespace
}  // namespace validation_test
