#pragma once
/// An assignment's rubric (assignments/<name>/rubric.toml): named checks with points and
/// visibility, each run in some worlds with some seeds, each judged by criteria from a fixed
/// vocabulary that the grader computes from the true trajectory. The format is described in
/// course/grading.md.

#include "frob/base/result.hpp"
#include "frob/worlds/generate.hpp"

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace frob::course {

/// Who sees a check's result on Gradescope.
enum class Visibility { Visible, Hidden, AfterDueDate };

/// One criterion of a check. Every robot of the world must meet it; point names may contain
/// "{robot}", replaced by each robot's name ("goal_{robot}").
struct Criterion {
  enum class Kind {
    Goal,        ///< within `distance` of point `point` by `seconds`
    Waypoints,   ///< within `distance` of each of `points`, in order, by `seconds`
    Stopped,     ///< moving slower than `speed` at the end; with an event, moving in the `within` s before it and slower from `within` s after it
    Collisions,  ///< at most `count` collisions (touches 0.5 s apart or more, one more per second of driving on while touching), and when `seconds` >
                 ///< 0 at most that long touching in all
    Clearance,   ///< the body never nearer a wall than `distance`
    WallDistance,  ///< the body `distance` ± `tolerance` from the nearest wall (on `side`, when given) for `fraction` of the run after `after` s
    Coverage,      ///< the robot's centre visited `fraction` of the free cells of size `cell` (of those whose body keeps `distance` from every wall)
    RobotsApart,   ///< robots' bodies never nearer each other than `distance`
    PathRatio,     ///< path until within `distance` of `point` at most `ratio` times the shortest collision-free path
    Bug1Bound,     ///< path until within `distance` of `point` at most the direct distance + 1.5 × the perimeters of obstacles met
    Returns,       ///< the top task returned `value` (reported by the controller), no sooner than the event it names and at most `within` s later
  };
  Kind kind = Kind::Goal;
  std::string point = "goal";
  std::vector<std::string> points;
  double distance = 0.0;
  double seconds = 0.0;  ///< 0: by the end of the run
  double speed = 0.02;
  int count = 0;
  double tolerance = 0.0;
  double fraction = 0.0;
  double after = 0.0;
  double cell = 0.5;
  double ratio = 1.0;
  std::string value;
  // The event a Stopped or Returns criterion follows, as the simulator saw it happen:
  char afterKey = 0;           ///< the first press of this key
  bool afterContact = false;   ///< the robot's first contact
  double afterDistance = 0.0;  ///< the robot's true path reaching this length, m (Returns only)
  double within = 0.0;         ///< Stopped: seconds allowed after the event (and moving in as many before it); Returns: the report's latency (0: 1 s)
  std::string side;            ///< WallDistance: "right" or "left" of the robot's heading; "": any wall
  int line = 0;                ///< where the rubric gives it
};

/// A world a check runs in: a reference world, a file beside the rubric, or a generated world.
struct WorldRef {
  std::string name;                            ///< as reports name it: "maze", "worlds/room.toml", "generated maze, seed 3"
  std::filesystem::path file;                  ///< the file, when it is not a reference world
  std::optional<worlds::WorldKind> generated;  ///< the kind, when it is generated
  std::uint64_t worldSeed = 0;                 ///< the generator's seed, when it is generated
};

/// The worlds a check generates: of one kind, from given seeds and from seeds of the instructor's secret.
struct GeneratedWorlds {
  worlds::WorldKind kind = worlds::WorldKind::Obstacles;
  std::vector<std::uint64_t> seeds;
  int secret = 0;  ///< how many more each submission runs in, drawn from the secret (named without their seed)
  int pool = 0;    ///< of how many fair draws of the secret a submission's `secret` are chosen, by its hash
  /// The pool's size: never fewer than the worlds a submission runs in.
  [[nodiscard]] int poolSize() const { return pool > secret ? pool : secret; }
};

/// One check: points for meeting every criterion, in every world with every seed.
struct Check {
  std::string name;
  double points = 1.0;
  Visibility visibility = Visibility::Visible;
  std::vector<WorldRef> worlds;  ///< the worlds it names (worldsOf() adds the generated ones)
  std::optional<GeneratedWorlds> generated;
  std::vector<std::uint64_t> seeds;  ///< simulation seeds; empty: one drawn (see seedsOf)
  int secretSeeds = 0;               ///< more seeds, drawn from the instructor's secret
  double seconds = 60.0;             ///< simulated seconds of each run
  /// `runs_of`: the earlier check whose runs it judges (their worlds, seeds and seconds, drawn by
  /// that check's name), each run made once for both; the first of a chain of runs_of; empty: runs
  /// of its own.
  std::string runsOf;
  std::vector<Criterion> criteria;
  int line = 0;
  /// The name its seeds and hidden worlds are drawn by: the check whose runs it judges, else its own.
  [[nodiscard]] const std::string& drawName() const { return runsOf.empty() ? name : runsOf; }
  /// Whether it needs the controller's task to return (a `returns` criterion): else the task may be
  /// meant to run for ever, as a wall follower's is.
  [[nodiscard]] bool waitsForAReturn() const;
};

/// A number Gradescope's leaderboard ranks submissions by: one criterion of a visible check, averaged
/// over the check's runs (a hidden check's would be a number the controller chooses, read by every student).
struct LeaderboardMetric {
  enum class Measure {
    Time,    ///< when the criterion was met, s (a goal or waypoints with `by`)
    Margin,  ///< by how much it was met, in the criterion's unit (Margin)
  };
  std::string name;  ///< the column Gradescope shows: "Time to the last waypoint (s)"
  std::string check;
  Criterion::Kind criterion = Criterion::Kind::Goal;
  Measure measure = Measure::Margin;
  bool ascending = false;  ///< smaller ranks first (Gradescope's "asc"); default: for a time, else larger first
  int line = 0;
};

/// An assignment's rubric.
struct Rubric {
  std::string title;
  std::filesystem::path file;       ///< the rubric file
  std::filesystem::path reference;  ///< the reference solution, which every hidden world must let pass; empty: none
  std::filesystem::path starter;    ///< the starter handed out, which no hidden world may let pass; empty: none
  double dt = 0.01;                 ///< the simulation step of every run
  std::vector<Check> checks;
  /// Lateness (`late = { per_day = 0.1, most = 0.5 }`): the share of the score taken for each day
  /// or part of one a submission comes after its due date, at most `most`; per_day 0: none.
  double latePerDay = 0.0;
  double lateMost = 1.0;
  std::vector<LeaderboardMetric> leaderboard;  ///< `[[leaderboard]]` entries, in order
  /// Total points.
  [[nodiscard]] double points() const;
  /// True when some check draws seeds or worlds from the instructor's secret.
  [[nodiscard]] bool needsSecret() const;
};

/// Reads `file`; every mistake (a typo, an unknown criterion, a missing world) is one message
/// naming the file, the line and the field, before anything runs.
[[nodiscard]] Result<Rubric> loadRubric(const std::filesystem::path& file);

/// Which of the worlds each check draws from the secret it keeps, by its drawName(): the indices of
/// the draws (0, 1, 2, ...) in its pool, in order. A check without an entry keeps the first `GeneratedWorlds::pool`.
using KeptWorlds = std::map<std::string, std::vector<int>>;

/// The seeds a check runs with: its own, then `secretSeeds` derived from `secret` and the check's
/// drawName(); when that makes none, one drawn from that name (and `secret` unless it is visible).
[[nodiscard]] std::vector<std::uint64_t> seedsOf(const Check& check, const std::string& secret);
/// The generator's seed of a check's draw `k` from the secret.
[[nodiscard]] std::uint64_t drawnWorldSeed(const Check& check, const std::string& secret, int k);
/// The worlds a check runs in: those it names, then those it generates: `secret` of its pool of the
/// secret's draws (those `kept` names for its drawName(), if any), chosen by `submission` (its
/// hash; "": the first ones), so that each submission is graded in worlds of its own.
[[nodiscard]] std::vector<WorldRef> worldsOf(const Check& check, const std::string& secret, const KeptWorlds& kept = {},
                                             const std::string& submission = "");
/// The rubric a student practises the hidden checks with: each check that draws worlds from the
/// secret, made visible and run instead in `worlds` worlds of its kind drawn from `seed` (never from
/// an instructor's secret); the other checks left out.
[[nodiscard]] Rubric practiceRubric(const Rubric& rubric, int worlds, std::uint64_t seed);
/// A world of a check, loaded or generated.
[[nodiscard]] Result<worlds::WorldDef> loadWorldRef(const WorldRef& world);

/// A criterion's name as a rubric writes it ("waypoints", "collisions").
[[nodiscard]] std::string_view toString(Criterion::Kind kind);
/// Readable name of a visibility, as Gradescope spells it ("visible", "hidden", "after_due_date").
[[nodiscard]] const char* toString(Visibility v);

}  // namespace frob::course
