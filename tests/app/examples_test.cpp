// The paper's programs (course/examples) run by the built frob, each checked on its trace for the
// behavior it teaches. Bounds come from runs on several seeds and steps; the reasons are given.
#include "run_frob.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace frob::testing {
namespace {

// A trace CSV as columns of numbers by name (an empty cell is NaN; the task column is dropped).
struct Trace {
  std::map<std::string, std::vector<double>> column;
  [[nodiscard]] std::size_t rows() const { return column.at("time").size(); }
  [[nodiscard]] double at(const std::string& name, std::size_t row) const { return column.at(name).at(row); }
  [[nodiscard]] int bumps() const {
    int n = 0;
    for (double b : column.at("bumper")) n += std::isnan(b) ? 0 : 1;
    return n;
  }
};

Trace readTrace(const std::filesystem::path& path) {
  std::stringstream in(readFile(path));
  std::string line, cell;
  std::getline(in, line);
  std::vector<std::string> names;
  for (std::stringstream h(line); std::getline(h, cell, ',');) names.push_back(cell);
  Trace t;
  while (std::getline(in, line)) {
    std::stringstream cells(line);
    for (std::size_t i = 0; i + 1 < names.size() && std::getline(cells, cell, ','); ++i) {
      t.column[names[i]].push_back(cell.empty() ? std::nan("") : std::stod(cell));
    }
  }
  return t;
}

// Runs example `name` with its own world and length; returns its trace and JSON summary.
std::pair<Trace, nlohmann::json> runExample(const std::string& name, const std::vector<std::string>& more = {}) {
  const std::filesystem::path dir = freshFolder("example_" + name);
  std::vector<std::string> args{"run", name, "--trace", "trace.csv", "--json", "--quiet"};
  args.insert(args.end(), more.begin(), more.end());
  const FrobResult r = runFrob(dir, args);
  EXPECT_EQ(r.status, 0) << r.err;
  return {readTrace(dir / "trace.csv"), nlohmann::json::parse(r.out)};
}

double finishedAt(const nlohmann::json& summary) {
  const nlohmann::json& f = summary["robots"][0]["finished_at"];
  return f.is_null() ? INFINITY : f.get<double>();
}

TEST(Examples, RunAroundNeverTouchesAWall) {
  auto [trace, summary] = runExample("01_run_around");
  EXPECT_DOUBLE_EQ(summary["simulated_seconds"].get<double>(), 60.0);
  EXPECT_EQ(trace.bumps(), 0);
  EXPECT_EQ(summary["robots"][0]["collisions"], 0);
  EXPECT_GE(summary["robots"][0]["distance"].get<double>(), 8.0);  // it wanders (13.8 m measured), not cowers
}

TEST(Examples, WallFollowerHoldsItsDistance) {
  auto [trace, summary] = runExample("02_wall_follower");
  // The left sonar (index 4, 90 degrees) against the 0.5 m setpoint once settled (5 s), while the
  // wall lasts (x <= 17.5 m). Measured <= 0.035 m on six seeds; sonar noise (1 % of range, about
  // +-2 cm here over thousands of samples) plus 1.5 cm of overshoot, with a margin of two.
  double worst = 0.0;
  std::size_t checked = 0;
  for (std::size_t k = 0; k < trace.rows(); ++k) {
    if (trace.at("time", k) < 5.0 || trace.at("true_x", k) > 17.5) continue;
    worst = std::max(worst, std::abs(0.5 - trace.at("s4", k)));
    ++checked;
  }
  EXPECT_GT(checked, 3000u);
  EXPECT_LE(worst, 0.08);
  EXPECT_EQ(trace.bumps(), 0);
}

TEST(Examples, StopitStopsBeforeTheWall) {
  auto [trace, summary] = runExample("03_stopit");
  EXPECT_EQ(trace.bumps(), 0);
  double maxX = 0.0;
  for (double x : trace.column.at("true_x")) maxX = std::max(maxX, x);
  EXPECT_LE(maxX, 6.0 - 0.23 - 0.1);  // the east wall at 6 m, less the radius and a 10 cm gap (0.17 m measured)
  EXPECT_LE(finishedAt(summary), 25.0);
}

TEST(Examples, DriveToArrives) {
  auto [trace, summary] = runExample("04_drive_to");
  EXPECT_LE(finishedAt(summary), 30.0);
  const std::size_t last = trace.rows() - 1;
  EXPECT_LE(std::hypot(trace.at("true_x", last) - 1.0, trace.at("true_y", last) - 1.0), 0.2);  // 0.10 m measured
}

TEST(Examples, CircleOnceReturnsToTheClosestPoint) {
  auto [trace, summary] = runExample("05_circle_once");
  EXPECT_LE(finishedAt(summary), 30.0);
  EXPECT_EQ(trace.bumps(), 0);
  // The point of the path round the pillar (3.6 to 16.7 s) closest to the goal (13, 13) is where it ends.
  double best = INFINITY, bx = 0, by = 0;
  for (std::size_t k = 0; k < trace.rows(); ++k) {
    const double t = trace.at("time", k), x = trace.at("true_x", k), y = trace.at("true_y", k);
    if (t < 3.6 || t > 16.7) continue;
    if (double d = std::hypot(13.0 - x, 13.0 - y); d < best) best = d, bx = x, by = y;
  }
  const std::size_t last = trace.rows() - 1;
  EXPECT_LE(std::hypot(trace.at("true_x", last) - bx, trace.at("true_y", last) - by), 0.35);  // 0.30 m measured
}

TEST(Examples, BugReachesTheGoal) {
  auto [trace, summary] = runExample("06_bug");
  const nlohmann::json& robot = summary["robots"][0];
  EXPECT_TRUE(robot["goal_reached"].get<bool>());
  EXPECT_LE(robot["goal_distance"].get<double>(), 0.5);
  EXPECT_LE(finishedAt(summary), 150.0);  // 126.5 s with the world's seed, 138.7 s on others
  EXPECT_EQ(trace.bumps(), 0);
}

TEST(Examples, WithTaskStopsAfterTenMetres) {
  auto [trace, summary] = runExample("07_with_task");
  EXPECT_GE(finishedAt(summary), 40.0);
  EXPECT_LE(finishedAt(summary), 55.0);
  EXPECT_NEAR(summary["robots"][0]["distance"].get<double>(), 10.0, 0.5);  // odometry's 10 m against the true path
}

TEST(Examples, OneControllerDrivesEveryRobotOfTheArena) {
  auto [trace, summary] = runExample("01_run_around", {"--world", "arena", "--seconds", "5"});
  ASSERT_EQ(summary["robots"].size(), 4u);
  EXPECT_EQ(trace.rows(), 4u * 500u);
  for (const nlohmann::json& r : summary["robots"]) EXPECT_GT(r["distance"].get<double>(), 0.5) << r["name"];
}

TEST(Examples, OneControllerPerRobotOfTheArena) {
  const std::filesystem::path dir = freshFolder("arena_each");
  const FrobResult r =
      runFrob(dir, {"run", "01_run_around", "03_stopit", "07_with_task", "bug", "--world", "arena", "--seconds", "2", "--json", "--quiet"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json summary = nlohmann::json::parse(r.out);
  std::vector<std::string> controllers;
  for (const nlohmann::json& robot : summary["robots"]) controllers.push_back(robot["controller"].get<std::string>().substr(0, 9));
  EXPECT_EQ(controllers, (std::vector<std::string>{"runAround", "stopitDem", "wanderTen", "bugToGoal"}));
}

}  // namespace
}  // namespace frob::testing
