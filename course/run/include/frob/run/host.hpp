#pragma once
/// Student controllers in a sandboxed process of their own: the controller host. The world, its
/// seed and every measurement stay here; the host only ever sees each robot's sensor frame and
/// answers its wheels (and, when a video is made, its picture and task timeline). A run gives each
/// robot a host of its own (RobotHosts).
///
///   Result<std::shared_ptr<ControllerHost>> host = ControllerHost::start({"wander.so"});
///   worlds::Run run(world, {}, (*host)->driver({0}, /*pictures=*/false));
///   run.runUntil(60);   // a crash, a hang or a forbidden call fails the robot with a reason

#include "frob/base/result.hpp"
#include "frob/controller.hpp"
#include "frob/run/controller_file.hpp"
#include "frob/sandbox/layers.hpp"
#include "frob/worlds/run.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace frob::course {

/// The limits of a controller host and how it waits for its turn.
struct HostDef {
  std::uint32_t robots = 1;                      ///< most robots it drives in one run (its channel is sized, then sealed, at start)
  double stepSeconds = 1.0;                      ///< wall-clock time one step of all its robots may take
  double startSeconds = 10.0;                    ///< to load the modules (global constructors run) and answer
  double runSeconds = 600.0;                     ///< wall-clock time of the whole run, and its CPU limit
  double paceAllowance = 10.0;                   ///< the grader's wait for a run's replies may pass the simulated time
  double pacePerSecond = 1.0;                    ///< driven by this much wall-clock time per simulated second, plus the allowance
  std::uint64_t memoryBytes = 1ULL << 30;        ///< its address space
  std::uint64_t outputBytes = 1ULL << 20;        ///< of its stdout and stderr passed on; the rest is dropped
  std::uint64_t fileBytes = 16ULL << 20;         ///< largest file it may write in its scratch folder
  std::uint64_t scratchBytes = 64ULL << 20;      ///< all the files it writes there
  std::uint64_t tasks = 64;                      ///< its processes and threads at once
  std::uint64_t spinNanoseconds = 50'000;        ///< the grader spins this long for a reply before it sleeps
  std::uint64_t hostSpinNanoseconds = 50'000;    ///< the host spins this long for its next frame before it sleeps: the same in
                                                 ///< every run of a grade, so that no controller can tell a hidden run by it
  std::function<void(std::string_view)> output;  ///< where its output goes; empty: this process's stderr
  std::filesystem::path program;                 ///< the host program; empty: frob-controller-host (frob::layout())
  bool checked = false;                          ///< its modules were compiled with compilerSetup(true): load the sanitizers' runtime,
                                                 ///< watch memory instead of limiting address space, and explain their reports
};

/// A controller host process with the modules it loaded. Killed, and its scratch folder removed,
/// when the last reference goes.
class ControllerHost : public std::enable_shared_from_this<ControllerHost> {
 public:
  /// Starts a sandboxed host that loads `modules` (compiled controller files, named in messages
  /// by `sources`). Fails with a reason when one cannot be loaded or its global constructors fail.
  [[nodiscard]] static Result<std::shared_ptr<ControllerHost>> start(const std::vector<std::filesystem::path>& modules,
                                                                     const std::vector<std::string>& sources, HostDef def = {});
  ~ControllerHost();
  ControllerHost(const ControllerHost&) = delete;
  ControllerHost& operator=(const ControllerHost&) = delete;

  /// What each module declared with FROB_CONTROLLER (its `make` is empty: it runs in the host).
  [[nodiscard]] const std::vector<ControllerEntry>& entries() const;
  /// Every layer of the sandbox, and whether it was applied.
  [[nodiscard]] const std::vector<sandbox::Layer>& layers() const;
  /// The driver of a run whose robot i runs module modulePerRobot[i] (one entry: all robots);
  /// with `pictures`, each robot's picture is kept in the run's record (the host samples and sends
  /// it in every run, so that a controller cannot tell a filmed run). A host drives one run.
  [[nodiscard]] worlds::DriverFactory driver(std::vector<std::size_t> modulePerRobot, bool pictures);
  /// The host's process id, for monitoring; 0 once it has ended and been reaped.
  [[nodiscard]] int processId() const;
  /// Things worth saying that are not failures, e.g. that output was dropped.
  [[nodiscard]] std::vector<std::string> notes() const;
  /// How many host processes this process has started, in all (what a run that is shared saves).
  [[nodiscard]] static std::uint64_t started();

  struct Impl;

 private:
  friend class RobotHosts;
  explicit ControllerHost(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

/// A host of its own for each robot of a run, so that robots share nothing but the world (no global
/// variable of one is another's). What `frob run` and `frob grade` drive a run with.
class RobotHosts {
 public:
  /// Starts one host per robot of `robots`: robot i runs modules[modulePerRobot[i]] (one entry:
  /// every robot runs it). Fails as ControllerHost::start() does.
  [[nodiscard]] static Result<RobotHosts> start(const std::vector<std::filesystem::path>& modules, const std::vector<std::string>& sources,
                                                const std::vector<std::size_t>& modulePerRobot, std::size_t robots, HostDef def = {});
  /// The driver of the run: each step every host gets its robot's frame before any answer is
  /// awaited; with `pictures`, each robot's picture is kept in the run's record.
  [[nodiscard]] worlds::DriverFactory driver(bool pictures) const;
  /// The sandbox's layers (each host has the same).
  [[nodiscard]] const std::vector<sandbox::Layer>& layers() const;
  /// Every host's notes, each once.
  [[nodiscard]] std::vector<std::string> notes() const;

 private:
  std::vector<std::shared_ptr<ControllerHost>> hosts_;
};

/// The layers that were needed and not applied, one line each ("landlock: NOT applied (...)"); "" when none.
[[nodiscard]] std::string missingLayers(const std::vector<sandbox::Layer>& layers);

/// What `compiled` declares, as a sandboxed host reports it: its code never runs in this process.
[[nodiscard]] Result<LoadedController> describeInHost(const CompiledController& compiled, HostDef def = {});

}  // namespace frob::course
