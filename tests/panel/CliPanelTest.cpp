// cube_game --panel from the command line: headless it renders and exits cleanly; a run that
// cannot have a panel is refused before a context is made.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <string>

#include "PanelTestUtil.h"
#include "RunCommand.h"

namespace {

using Result = cubetest::CommandResult;

Result runGame(const std::string& args) {
    return cubetest::runCommand(std::string(CUBE_TEST_BIN_DIR) + "/cube_game " + args + " 2>&1", 128);
}

}  // namespace

TEST(CliPanel, HeadlessPanelRunsWithoutGlErrorsAndItsPassIsInTheFrame) {
    paneltest::ReactionCopy copy;
    const std::string stats = copy.dir() + "/stats.json";
    const Result r = runGame("--panel --frames 12 --fixed-dt 0.0166667 --size 640x480 --reactions " + copy.dir() +
                             " --stats-json " + stats);
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string json = paneltest::readFile(stats);
    EXPECT_NE(json.find("\"gl_errors\": 0"), std::string::npos) << json;
    EXPECT_NE(json.find("\"panel\""), std::string::npos) << "no panel pass ran: " << json;
}

TEST(CliPanel, PanelWithLegacySmokeIsRefusedNamingTheFlags) {
    const Result r = runGame("--panel --fx legacy --frames 1");
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("--panel: edits the plugin's reactions; expected --fx plugin"), std::string::npos) << r.output;
}
