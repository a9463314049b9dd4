#include "dream/view/frame_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

namespace dream::view {
namespace {

ViewFrame TwoRobots() {
  ViewFrame frame;
  frame.run_id = 9007199254740993;  // 2^53 + 1: not a JavaScript number
  frame.step = 42;
  frame.utime = 42 * 33000;
  frame.x_m = {0.5, -1.25};
  frame.y_m = {0.123456, 0.0};
  frame.theta_rad = {M_PI / 2, -0.1};
  frame.v_mps = {0.123456, -0.05};
  frame.w_radps = {1.0, -2.5};
  frame.obstacles.push_back({3, 0.1, 0.2, 0.3, 0.4, 0.05, 0.0});
  frame.status.seen = true;
  frame.status.state = 1;
  frame.status.collision_errors = 2;
  frame.status.lost_robot_ids = {1};
  frame.status.detail = "running";
  frame.radio_senders = {0};
  frame.radio_links = {{0, 1}};
  frame.violations.push_back({ViolationMark::Kind::kCollision, 41, 0, 1, 0.25, 0.1});
  frame.violations_located = 7;
  return frame;
}

TEST(FrameJsonTest, WritesWhatThePageReads) {
  const nlohmann::json json = nlohmann::json::parse(FrameJson(TwoRobots()));
  EXPECT_EQ(json["type"], "frame");
  EXPECT_EQ(json["run"], "9007199254740993");  // a string, exact
  EXPECT_EQ(json["step"], 42);
  EXPECT_DOUBLE_EQ(json["t"].get<double>(), 1.386);
  EXPECT_EQ(json["x"], nlohmann::json::parse("[0.5,-1.25]"));
  EXPECT_DOUBLE_EQ(json["y"][0].get<double>(), 0.1235);  // to 0.1 mm
  EXPECT_DOUBLE_EQ(json["th"][0].get<double>(), 1.5708);
  EXPECT_EQ(json["v"], nlohmann::json::parse("[0.1235,-0.05]"));  // what each robot drove with, for the arrows
  EXPECT_EQ(json["w"], nlohmann::json::parse("[1,-2.5]"));
  EXPECT_FALSE(json.contains("mx"));  // no measured poses: none sent
  EXPECT_EQ(json["obstacles"], nlohmann::json::parse("[[3,0.1,0.2,0.3,0.4,0.05,0]]"));
  EXPECT_EQ(json["status"]["collision"], 2);
  EXPECT_EQ(json["status"]["lost"], nlohmann::json::parse("[1]"));
  EXPECT_EQ(json["radio"], nlohmann::json::parse("[0]"));
  EXPECT_EQ(json["links"], nlohmann::json::parse("[[0,1]]"));
  ASSERT_EQ(json["violations"].size(), 1u);
  EXPECT_EQ(json["violations"][0]["kind"], "collision");
  EXPECT_EQ(json["violations"][0]["step"], 41);
  EXPECT_EQ(json["violations"][0]["other"], 1);
  EXPECT_EQ(json["located"], 7);
  EXPECT_TRUE(json["other_world"].is_null());  // alone on the bus
  EXPECT_TRUE(json["judged"].is_null());       // not judged yet
}

TEST(FrameJsonTest, CarriesTheWorldsVerdictOnceTheRunIsJudged) {
  ViewFrame frame = TwoRobots();
  frame.judged = ViewFrame::Judged{"not_ready",
                                   "missed (worst 0.0200082 m, tolerance 0.02 m)",
                                   5,
                                   {"goal: the go_to_goal experiment missed its goal"}};
  const nlohmann::json json = nlohmann::json::parse(FrameJson(frame));
  // As the setup's "judged" (summary.json's in a replay): what the page ends the run on.
  EXPECT_EQ(json["judged"]["verdict"], "not_ready");
  EXPECT_EQ(json["judged"]["goal"], "missed (worst 0.0200082 m, tolerance 0.02 m)");
  EXPECT_EQ(json["judged"]["exit_code"], 5);
  EXPECT_EQ(json["judged"]["reasons"], nlohmann::json::parse(R"(["goal: the go_to_goal experiment missed its goal"])"));
  EXPECT_EQ(json["judged"]["metrics"], nlohmann::json::array());
}

TEST(FrameJsonTest, ASecondWorldOnTheBusIsSaid) {
  ViewFrame frame = TwoRobots();
  frame.other_world = ViewFrame::OtherWorld{-2, 0, 0, 3};  // a run id above 2^63, as int64
  nlohmann::json json = nlohmann::json::parse(FrameJson(frame));
  EXPECT_EQ(json["other_world"]["run"], "-2");  // a string, exact, as "run" is
  EXPECT_EQ(json["other_world"]["step"], 0);
  EXPECT_EQ(json["other_world"]["state"], 0);  // waiting for agents
  EXPECT_EQ(json["other_world"]["runs"], 3);
  frame.other_world->state = -1;  // poses heard, no status
  json = nlohmann::json::parse(FrameJson(frame));
  EXPECT_TRUE(json["other_world"]["state"].is_null());
}

TEST(FrameJsonTest, MeasuredPosesAreSentWhenThere) {
  ViewFrame frame = TwoRobots();
  frame.measured_x_m = {0.51, -1.24};
  frame.measured_y_m = {0.12, 0.01};
  frame.measured_theta_rad = {1.5, -0.2};
  const nlohmann::json json = nlohmann::json::parse(FrameJson(frame));
  EXPECT_EQ(json["mx"], nlohmann::json::parse("[0.51,-1.24]"));
  EXPECT_EQ(json["mth"].size(), 2u);
}

TEST(FrameJsonTest, NumbersThatAreNotFiniteBecomeNull) {
  ViewFrame frame = TwoRobots();
  frame.x_m[0] = std::numeric_limits<double>::quiet_NaN();
  frame.y_m[1] = std::numeric_limits<double>::infinity();
  frame.theta_rad[1] = 1e300;  // finite, but no position: too long for the writer
  const std::string text = FrameJson(frame);
  const nlohmann::json json = nlohmann::json::parse(text);  // still JSON
  EXPECT_TRUE(json["x"][0].is_null());
  EXPECT_TRUE(json["y"][1].is_null());
  EXPECT_TRUE(json["th"][1].is_null());
}

TEST(FrameJsonTest, ForgedTextIsValidUtf8AndEscaped) {
  ViewFrame frame = TwoRobots();
  const char forged[] = "quote \" backslash \\ newline \n bell \a bad \xff\xfe end \xc3\xa9 \xe2\x80\x94";
  frame.status.detail = std::string(forged, sizeof forged - 1);
  const std::string text = FrameJson(frame);
  const nlohmann::json json = nlohmann::json::parse(text);  // throws on invalid UTF-8
  const std::string detail = json["status"]["detail"];
  EXPECT_NE(detail.find("quote \" backslash \\ newline \n bell \a bad "), std::string::npos);
  EXPECT_NE(detail.find("\xef\xbf\xbd\xef\xbf\xbd end"), std::string::npos);  // each bad byte: U+FFFD
  EXPECT_NE(detail.find("\xc3\xa9 \xe2\x80\x94"), std::string::npos);         // good UTF-8 kept
}

TEST(FrameJsonTest, AFrameBeforeAnyPosesHasNoRobotsAndNoStatus) {
  const nlohmann::json json = nlohmann::json::parse(FrameJson(ViewFrame()));
  EXPECT_EQ(json["step"], -1);
  EXPECT_TRUE(json["x"].empty());
  EXPECT_TRUE(json["status"].is_null());
}

TEST(FrameJsonTest, SetupSaysTheArenaAndTheConfigsGoals) {
  ViewSetup setup;
  setup.mode = ViewSetup::Mode::kReplay;
  setup.source = "runs/ring";
  setup.overlays.goals_m = {{{0.5, 0.25}}, {}};
  setup.overlays.sensor_reaches = {{1.0, 0.0, M_PI}};
  setup.overlays.run_name = "ring";
  setup.frame_rates = FrameRates::One(12);
  const nlohmann::json json = nlohmann::json::parse(SetupJson(setup));
  EXPECT_EQ(json["type"], "setup");
  EXPECT_EQ(json["mode"], "replay");
  EXPECT_EQ(json["arena"], nlohmann::json::parse("[-1.6,1.6,-1,1]"));
  EXPECT_DOUBLE_EQ(json["robot_diameter"].get<double>(), 0.11);
  EXPECT_DOUBLE_EQ(json["time_step"].get<double>(), 0.033);
  EXPECT_EQ(json["goals"], nlohmann::json::parse("[[[0.5,0.25]],[]]"));
  EXPECT_DOUBLE_EQ(json["sensors"][0][2].get<double>(), 3.1416);
  EXPECT_EQ(json["run_name"], "ring");
  EXPECT_FALSE(json["hears_known"].get<bool>());
  EXPECT_EQ(json["fps"], 12);  // the page draws no more often than frames come
}

// One judge (issue 33): a replay's setup carries the run's summary.json
// verdict, goal and metrics, which the page shows at the run's end.
TEST(FrameJsonTest, ASetupCarriesTheRunsJudgementWhenItHasOne) {
  ViewSetup setup;
  setup.mode = ViewSetup::Mode::kReplay;
  EXPECT_EQ(SetupJson(setup).find("\"judged\""), std::string::npos);
  setup.judged = ViewSetup::Judged{"not_ready",
                                   {"goal: the go_to_goal experiment missed its goal"},
                                   "missed (worst 0.03 m)",
                                   {{"final_max_goal_error_m", "0.03"}, {"all_arrived_step", "-1"}}};
  const std::string json = SetupJson(setup);
  EXPECT_NE(
      json.find(
          "\"judged\":{\"verdict\":\"not_ready\",\"reasons\":[\"goal: the go_to_goal experiment missed its goal\"],"
          "\"goal\":\"missed (worst 0.03 m)\",\"metrics\":[[\"final_max_goal_error_m\",\"0.03\"],"
          "[\"all_arrived_step\",\"-1\"]]}"),
      std::string::npos)
      << json;
}

}  // namespace
}  // namespace dream::view
