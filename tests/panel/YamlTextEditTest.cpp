// In-place text edits at yaml-cpp's positions: only the edited characters change.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include "panel/YamlTextEdit.h"

using namespace cube::panel;

namespace {

const char* kText =
    "# a comment\n"
    "reactions:\n"
    "  - name: smoke\n"
    "    particle:\n"
    "      lifetime: [3.0, 5.0]     # seconds\n"
    "      drag: 1.2                # inherited speed halves\n"
    "      label: 'it''s'\n"
    "      quoted: \"1.5\"\n"
    "      colour_ramp:\n"
    "        - {t: 0.0, rgba: [0.93, 0.93, 0.92, 0.85]}\n"
    "        - {t: 1.0, rgba: [0.78, 0.78, 0.79, 0.45]}\n"
    "    # render settings follow\n"
    "    render:\n"
    "      technique: soft\n";

YAML::Node particle(const std::string& text) { return YAML::Load(text)["reactions"][0]["particle"]; }

}  // namespace

TEST(YamlTextEdit, PlainScalarIsReplacedAndNothingElse) {
    std::string text = kText, error;
    ASSERT_TRUE(replaceScalar(&text, particle(text)["drag"], "2.5", &error)) << error;
    std::string expected = kText;
    expected.replace(expected.find("drag: 1.2") + 6, 3, "2.5");
    EXPECT_EQ(text, expected);
}

TEST(YamlTextEdit, FlowSequenceElementIsReplacedInPlace) {
    std::string text = kText, error;
    ASSERT_TRUE(replaceScalar(&text, particle(text)["lifetime"][1], "6.5", &error)) << error;
    EXPECT_NE(text.find("      lifetime: [3.0, 6.5]     # seconds\n"), std::string::npos);
    EXPECT_EQ(text.size(), std::string(kText).size());
}

TEST(YamlTextEdit, ColourRampComponentInAFlowMapIsReplacedInPlace) {
    std::string text = kText, error;
    ASSERT_TRUE(replaceScalar(&text, particle(text)["colour_ramp"][1]["rgba"][3], "0.3", &error)) << error;
    EXPECT_NE(text.find("        - {t: 1.0, rgba: [0.78, 0.78, 0.79, 0.3]}\n"), std::string::npos);
    EXPECT_EQ(YAML::Load(text)["reactions"][0]["particle"]["colour_ramp"][1]["rgba"][3].as<float>(), 0.3f);
}

TEST(YamlTextEdit, QuotedScalarsKeepTheirQuotes) {
    std::string text = kText, error;
    ASSERT_TRUE(replaceScalar(&text, particle(text)["quoted"], "2.5", &error)) << error;
    EXPECT_NE(text.find("quoted: \"2.5\"\n"), std::string::npos);
    ASSERT_TRUE(replaceScalar(&text, particle(text)["label"], "o'k", &error)) << error;
    EXPECT_NE(text.find("label: 'o''k'\n"), std::string::npos);
    EXPECT_EQ(particle(text)["label"].Scalar(), "o'k");
}

TEST(YamlTextEdit, WholeFlowSequenceSpanCoversItsBrackets) {
    const std::string text = kText;
    TextSpan span;
    std::string error;
    ASSERT_TRUE(valueSpan(text, particle(text)["lifetime"], &span, &error)) << error;
    EXPECT_EQ(text.substr(span.begin, span.end - span.begin), "[3.0, 5.0]");
    // A block collection has no single span to rewrite.
    EXPECT_FALSE(valueSpan(text, particle(text)["colour_ramp"], &span, &error));
    EXPECT_NE(error.find("block collection"), std::string::npos) << error;
}

TEST(YamlTextEdit, AKeyIsAppendedToItsBlockMapBeforeTheNextSectionsComment) {
    std::string text = kText, error;
    ASSERT_TRUE(appendToBlockMap(&text, particle(text), "rise_speed", "0.4", &error)) << error;
    // After the ramp's last line, indented like the map's keys, before "# render settings".
    EXPECT_NE(text.find("0.45]}\n      rise_speed: 0.4\n    # render settings follow\n"), std::string::npos) << text;
    EXPECT_EQ(particle(text)["rise_speed"].as<float>(), 0.4f);
    EXPECT_EQ(YAML::Load(text)["reactions"][0]["render"]["technique"].Scalar(), "soft");
}

TEST(YamlTextEdit, SequenceItemLineIsTheWholeLine) {
    const std::string text = kText;
    TextSpan span;
    std::string error;
    ASSERT_TRUE(sequenceItemLine(text, particle(text)["colour_ramp"][0], &span, &error)) << error;
    EXPECT_EQ(text.substr(span.begin, span.end - span.begin), "        - {t: 0.0, rgba: [0.93, 0.93, 0.92, 0.85]}\n");
}

TEST(YamlTextEdit, NumbersAreWrittenShortAndKeepADecimalPointWhenTheOldTextHadOne) {
    EXPECT_EQ(formatNumber(2.5, false), "2.5");
    EXPECT_EQ(formatNumber(0.1f, false), "0.1");
    EXPECT_EQ(formatNumber(3.0, false, "2.0"), "3.0");
    EXPECT_EQ(formatNumber(3.0, false, "90"), "3");
    EXPECT_EQ(formatNumber(2047.6, true), "2048");
}
