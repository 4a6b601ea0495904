#include "frob/worlds/simulation.hpp"

#include "frob/errors.hpp"
#include "frob/worlds/fnv.hpp"
#include "random.hpp"
#include "ray_caster.hpp"
#include "workers.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <utility>

namespace frob::worlds {
namespace {

constexpr int kVelocityIterations = 8;
constexpr int kPositionIterations = 3;
// Robots per chunk of parallel work at least (Workers makes up to 16 chunks per thread), so that a
// chunk is some 50 us of work, worth its claim (about 1 us): sensing a robot costs some 4 us, noisy
// odometry some 0.15 us.
constexpr std::size_t kSenseGrain = 12;
constexpr std::size_t kOdometryGrain = 256;
// Continuous collision is on when a robot can cover more than this part of its radius in a step.
constexpr double kTunnelFraction = 0.25;

// The directions of a robot's sonar rays relative to its heading, per sonar, per ray. Robots
// alike share one, so that sensing a crowd reads them from the cache rather than memory.
struct Rays {
  std::vector<double> x, y;
  detail::Spread spread;  // the widest any cone's rays stray from its first
  bool operator==(const Rays& o) const { return x == o.x && y == o.y; }
};

// One robot's state apart from its Box2D body.
struct RobotState {
  RobotDef def;
  RobotSpec spec;
  b2Body* body = nullptr;
  std::shared_ptr<const Rays> rays;
  std::vector<Vec2> sonarOffsets;  // per sonar: sensor position relative to the centre, robot frame
  double cosCutoff = 1.0;
  double forward = 0.0, turn = 0.0;  // commands after acceleration limits
  Pose2 odometry;
  Pose2 previous;                            // true pose at the end of the last step: the body's own until the next
  double previousCos, previousSin;           // of its heading, for dead reckoning and sensing alike
  bool exactOdometry = true;                 // no noise and no start offset: odometry is the true pose
  double slipForward = 0.0, slipTurn = 0.0;  // relative errors of the achieved speeds, this step
  double slipDecay = 1.0, slipKick = 0.0;    // per step: how much of the error stays, and the new part's deviation
  std::vector<int> pressed;                  // per bumper: contacts touching it
  std::vector<BumperHit> bumps;              // bumper contacts that began during the last step
  std::size_t invalid = 0;
  detail::Rng sonarRng, odometryRng, slipRng;
  SensorFrame frame;
  // The sonars' last echoes before noise, and the heading they were cast from (NaN: none yet).
  std::vector<double> echoes;
  double echoedHeading = NAN;
};

// A touching contact and the bumper it pressed.
struct Press {
  b2Contact* contact;
  int robot, bumper;
};

// Equal to the bit: -0 is not 0, and a NaN may equal itself.
bool sameBits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

Pose2 poseOf(const b2Body* body) {
  const b2Vec2 p = body->GetPosition();
  return {Point2(p.x, p.y), wrapAngle(body->GetAngle())};
}

}  // namespace

struct Simulation::Impl : b2ContactListener {
  WorldDef world;
  std::vector<WallDef> walls;
  SimOptions options;
  std::uint64_t seed = 1;
  b2World physics{b2Vec2(0.0f, 0.0f)};
  std::vector<RobotState> robots;
  std::vector<Press> presses;
  using Keys = std::vector<std::pair<std::int64_t, KeyEventDef>>;
  Keys keys;  // (step, key), sorted by step
  detail::RayCaster caster;
  detail::Workers workers;
  std::int64_t steps = 0;
  std::vector<Point2> centres;
  std::vector<double> radii;
  bool robotsMoved = true;                               // some robot's centre differs from the last sense()'s: every echo is cast anew
  double reach = 0.0;                                    // the farthest any sonar hears from its robot's centre: its range plus the rim
  std::vector<std::shared_ptr<const Rays>> rayPatterns;  // the distinct ones
  // The last step's dead reckoning is still to do. Each robot's is done as it is next sensed, in
  // parallel and while its state is at hand (a separate pass over all robots cost 1000 robots a
  // tenth of a step), or when a step or odometry() comes first.
  bool odometryPending = false;

  Impl(const WorldDef& w, const SimOptions& o)
      : world(w),
        walls(withEnclosure(w)),
        options(o),
        seed(o.seed.value_or(w.seed)),
        caster(walls, Point2(-1.0, -1.0), w.size + Point2(1.0, 1.0), sensingOf(w)),
        workers(o.threads) {
    FROB_ASSERT(o.dt > 0 && std::isfinite(o.dt), "SimOptions::dt must be positive");
    physics.SetContactListener(this);
    buildWalls();
    for (std::size_t i = 0; i < w.robots.size(); ++i) addRobot(w.robots[i], i);
    physics.SetContinuousPhysics(mayTunnel());
    for (const auto& list : {w.keys, o.keys})
      for (const KeyEventDef& k : list) keys.emplace_back(static_cast<std::int64_t>(std::ceil(k.time / o.dt - 1e-9)), k);
    std::stable_sort(keys.begin(), keys.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  }

  // How the robots' sonars sweep the walls: the longest range and the widest cone, for which the
  // ray caster sizes its grid.
  static detail::Sensing sensingOf(const WorldDef& w) {
    detail::Sensing s;
    for (const RobotDef& r : w.robots) s.range = std::max(s.range, r.sonar.maxRange), s.cone = std::max(s.cone, r.sonar.cone);
    return s;
  }

  // Box2D's continuous collision (time of impact for every contact, a tenth of a 100-robot step)
  // only matters when a robot can move a sizeable part of its radius in one step; otherwise the
  // position solver keeps discs out of walls.
  bool mayTunnel() const {
    return std::any_of(robots.begin(), robots.end(),
                       [&](const RobotState& r) { return r.def.drive.maxSpeed * options.dt > kTunnelFraction * r.def.radius; });
  }

  static std::vector<WallDef> withEnclosure(const WorldDef& w) {
    std::vector<WallDef> all = w.walls;
    if (w.enclosed) {
      const Point2 a(0, 0), b(w.size.x(), 0), c = w.size, d(0, w.size.y());
      for (auto [p, q] : {std::pair{a, b}, {b, c}, {c, d}, {d, a}}) all.push_back(segmentWall(p, q));
    }
    return all;
  }

  void buildWalls() {
    b2BodyDef def;
    b2Body* ground = physics.CreateBody(&def);
    auto v = [](const Point2& p) { return b2Vec2(static_cast<float>(p.x()), static_cast<float>(p.y())); };
    auto edge = [&](const Point2& a, const Point2& b) {
      b2EdgeShape e;
      e.SetTwoSided(v(a), v(b));
      ground->CreateFixture(&e, 0.0f);
    };
    auto block = [&](const Point2& lo, const Point2& hi) {
      b2PolygonShape box;
      const Vec2 half = (hi - lo) / 2;
      box.SetAsBox(static_cast<float>(half.x()), static_cast<float>(half.y()), v(lo + half), 0.0f);
      ground->CreateFixture(&box, 0.0f);
    };
    auto disc = [&](const Point2& centre, double radius) {
      b2CircleShape c;
      c.m_p = v(centre);
      c.m_radius = static_cast<float>(radius);
      ground->CreateFixture(&c, 0.0f);
    };
    for (const WallDef& w : walls) forEachEdge(w, edge, block, disc);
  }

  void addRobot(const RobotDef& d, std::size_t index) {
    RobotState r;
    r.def = d;
    r.spec = robotSpec(d);
    const Pose2 known = knownStart(d, index), truth = trueStart(d, known, index);
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(static_cast<float>(truth.position.x()), static_cast<float>(truth.position.y()));
    def.angle = static_cast<float>(truth.heading);
    def.fixedRotation = true;  // synchro drive: the body turns only when commanded
    r.body = physics.CreateBody(&def);
    b2CircleShape disc;
    disc.m_radius = static_cast<float>(d.radius);
    b2FixtureDef fixture;
    fixture.shape = &disc;
    fixture.density = static_cast<float>(d.density);
    fixture.friction = 0.0f;
    fixture.restitution = 0.0f;
    fixture.userData.pointer = index + 1;  // 0 marks walls
    r.body->CreateFixture(&fixture);

    // Ray directions spread evenly across each cone; sensors sit on the body's rim.
    const SonarDef& s = d.sonar;
    Rays rays;
    for (double a : r.spec.sonarAngles) {
      r.sonarOffsets.push_back(d.radius * unitVector(a));
      // Axis first, then alternately left and right moving outwards: 0, +1, -1, +2, -2 steps.
      const double spacing = s.rays == 1 ? 0.0 : s.cone / (s.rays - 1);
      const double centre = (s.rays - 1) / 2.0;
      std::vector<double> offsets;
      for (int k = 0; k < s.rays; ++k) offsets.push_back((k - centre) * spacing);
      std::stable_sort(offsets.begin(), offsets.end(),
                       [](double x, double y) { return std::abs(x) < std::abs(y) || (std::abs(x) == std::abs(y) && x > y); });
      for (double off : offsets) {
        const Vec2 u = unitVector(a + off);
        rays.x.push_back(u.x()), rays.y.push_back(u.y());
      }
      const std::size_t first = rays.x.size() - offsets.size();
      const detail::Spread cone = detail::spreadOf({&rays.x[first], offsets.size()}, {&rays.y[first], offsets.size()});
      rays.spread = {std::min(rays.spread.cos, cone.cos), std::max(rays.spread.sin, cone.sin)};
    }
    const auto same = std::find_if(rayPatterns.begin(), rayPatterns.end(), [&](const auto& p) { return *p == rays; });
    r.rays = same != rayPatterns.end() ? *same : rayPatterns.emplace_back(std::make_shared<const Rays>(std::move(rays)));
    reach = std::max(reach, s.maxRange + d.radius);
    r.cosCutoff = std::cos(s.specularCutoff);
    r.previous = poseOf(r.body);
    r.previousCos = std::cos(r.previous.heading), r.previousSin = std::sin(r.previous.heading);
    const bool offset = truth.position != known.position || truth.heading != known.heading;
    r.odometry = offset ? Pose2{known.position, wrapAngle(known.heading)} : r.previous;
    r.exactOdometry = !offset && d.odometry.translation == 0 && d.odometry.heading == 0 && d.odometry.turn == 0;
    r.pressed.assign(static_cast<std::size_t>(d.bumpers), 0);
    r.sonarRng = detail::Rng(seed, index, detail::Stream::Sonar);
    r.odometryRng = detail::Rng(seed, index, detail::Stream::Odometry);
    r.slipRng = detail::Rng(seed, index, detail::Stream::Slip);
    if (d.drive.slip > 0) {  // an Ornstein-Uhlenbeck process per speed, begun in its steady spread
      r.slipDecay = std::exp(-options.dt / d.drive.slipTime);
      r.slipKick = d.drive.slip * std::sqrt(1.0 - r.slipDecay * r.slipDecay);
      r.slipForward = d.drive.slip * r.slipRng.gaussian();
      r.slipTurn = d.drive.slip * r.slipRng.gaussian();
    }
    r.frame.sonar.assign(r.spec.sonarAngles.size(), s.maxRange);
    r.frame.odometry = r.odometry;
    robots.push_back(std::move(r));
  }

  // `from` moved by an offset drawn from `stream` uniformly within `position` metres and `heading` radians.
  Pose2 drawnNear(const Pose2& from, double position, double heading, std::size_t index, detail::Stream stream) const {
    if (position == 0 && heading == 0) return from;
    detail::Rng rng(seed, index, stream);
    const double distance = position * std::sqrt(rng.uniform()), direction = 2 * pi * rng.uniform();
    const double turn = heading * (2 * rng.uniform() - 1);
    return {from.position + distance * unitVector(direction), wrapAngle(from.heading + turn)};
  }
  // Robot `index`'s starting pose as it knows it, where its odometry begins.
  Pose2 knownStart(const RobotDef& d, std::size_t index) const {
    return drawnNear(d.start, d.startSpread.knownPosition, d.startSpread.knownHeading, index, detail::Stream::KnownStart);
  }
  // Robot `index`'s true starting pose, within the start spread of the `known` one.
  Pose2 trueStart(const RobotDef& d, const Pose2& known, std::size_t index) const {
    return drawnNear(known, d.startSpread.position, d.startSpread.heading, index, detail::Stream::Start);
  }

  // Box2D calls this during Step when two fixtures start touching.
  void BeginContact(b2Contact* contact) override {
    b2WorldManifold m;
    contact->GetWorldManifold(&m);
    const int n = contact->GetManifold()->pointCount;
    if (n == 0) return;
    b2Vec2 at = m.points[0];
    if (n == 2) at = 0.5f * (m.points[0] + m.points[1]);
    for (b2Fixture* f : {contact->GetFixtureA(), contact->GetFixtureB()}) {
      const std::uintptr_t id = f->GetUserData().pointer;
      if (id == 0) continue;
      RobotState& r = robots[id - 1];
      const b2Vec2 c = r.body->GetPosition();
      const double angle = angleDiff(r.body->GetAngle(), std::atan2(double(at.y) - c.y, double(at.x) - c.x));
      const double sector = 2.0 * pi / r.def.bumpers;
      const int bumper = static_cast<int>(std::floor(std::fmod(angle + sector / 2 + 2 * pi, 2 * pi) / sector)) % r.def.bumpers;
      presses.push_back({contact, static_cast<int>(id - 1), bumper});
      // A bumper switch closes once however many things press it.
      if (r.pressed[bumper]++ == 0) r.bumps.push_back({bumper, angle});
    }
  }

  void EndContact(b2Contact* contact) override {
    for (std::size_t k = 0; k < presses.size();) {
      if (presses[k].contact == contact) {
        --robots[presses[k].robot].pressed[presses[k].bumper];
        presses[k] = presses.back();
        presses.pop_back();
      } else {
        ++k;
      }
    }
  }

  // Scratch for sensing, one per thread rather than per robot, so that a step touches less memory.
  struct SenseScratch {
    std::vector<double> worldX, worldY;  // the rays in the world frame
    std::vector<Point2> origins;         // the sonars in the world frame
    detail::Neighbours near;
  };

  // The sensor frame of robot `i`, with the keys from `keysNow` on that fall in this step. Sonars
  // read per sonar the nearest echoing ray, with noise proportional to range.
  void senseRobot(std::size_t i, Keys::const_iterator keysNow, SenseScratch& scratch) {
    RobotState& r = robots[i];
    SensorFrame& f = r.frame;
    const SonarDef& s = r.def.sonar;
    // The body has not moved since its odometry was last brought up to date.
    const Pose2& pose = r.previous;
    const double c = r.previousCos, sn = r.previousSin;
    if (!robotsMoved && sameBits(pose.heading, r.echoedHeading)) {
      // No robot moved and this one has not turned: the cones would meet what they met before.
      std::copy(r.echoes.begin(), r.echoes.end(), f.sonar.begin());
    } else if (!r.sonarOffsets.empty()) {
      const Rays& rays = *r.rays;
      std::vector<double>&worldX = scratch.worldX, &worldY = scratch.worldY;
      worldX.resize(rays.x.size()), worldY.resize(rays.y.size());
      for (std::size_t k = 0; k < rays.x.size(); ++k) {  // every ray at once: the compiler vectorises it
        worldX[k] = c * rays.x[k] - sn * rays.y[k];
        worldY[k] = sn * rays.x[k] + c * rays.y[k];
      }
      scratch.origins.clear();
      for (const Vec2& o : r.sonarOffsets) scratch.origins.emplace_back(pose.position + Vec2(c * o.x() - sn * o.y(), sn * o.x() + c * o.y()));
      // Rays run from the cone's axis outwards, each only as far as the nearest echo so far: a
      // surface beyond it cannot change the reading, and the shorter walk saves most of the work.
      // A hit whose cosIncidence is below the cutoff is reflected away and does not echo.
      caster.gather(pose.position, r.def.radius, s.maxRange, static_cast<int>(i), scratch.near);
      caster.castCones(scratch.origins, worldX, worldY, rays.spread, s.maxRange, r.cosCutoff, scratch.near, f.sonar);
      r.echoes.assign(f.sonar.begin(), f.sonar.end());
      r.echoedHeading = pose.heading;
    }
    for (double& reading : f.sonar) {
      const double noise = r.sonarRng.gaussian();  // drawn for every sonar so the stream never depends on hits
      reading = reading >= s.maxRange ? s.maxRange : std::clamp(reading * (1.0 + s.noise * noise), s.minRange, s.maxRange);
    }
    const b2Vec2 v = r.body->GetLinearVelocity();
    f.odometry = r.odometry;
    f.velocity = c * v.x + sn * v.y;
    f.turnRate = r.body->GetAngularVelocity();
    f.bumps = r.bumps;
    f.keys.clear();
    for (auto k = keysNow; k != keys.end() && k->first == steps; ++k)
      if (k->second.robot < 0 || static_cast<std::size_t>(k->second.robot) == i) f.keys.push_back(k->second.key);
  }

  // Brings every robot's belief up to the last step, unless sense() already has.
  void settleOdometry() {
    if (!odometryPending) return;
    odometryPending = false;
    workers.run(robots.size(), kOdometryGrain, [this](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) updateOdometry(robots[i]);
    });
  }

  // Dead reckoning: the true motion of the last step in the robot's frame, with noise, added to the belief.
  void updateOdometry(RobotState& r) {
    const Pose2 now = poseOf(r.body);
    const Pose2 before = r.previous;
    const double c = r.previousCos, s = r.previousSin;
    r.previous = now;
    r.previousCos = std::cos(now.heading), r.previousSin = std::sin(now.heading);
    if (r.exactOdometry) {
      r.odometry = now;
      return;
    }
    const Vec2 d = now.position - before.position;
    double dx = c * d.x() + s * d.y();
    const double dy = -s * d.x() + c * d.y();
    double dh = angleDiff(before.heading, now.heading);
    const OdometryDef& o = r.def.odometry;
    if (o.translation != 0 || o.heading != 0 || o.turn != 0) {
      const double g1 = r.odometryRng.gaussian(), g2 = r.odometryRng.gaussian();
      const double dist = std::abs(dx), turned = std::abs(dh);
      dx += o.translation * std::sqrt(dist) * g1;
      dh += std::sqrt(o.heading * o.heading * dist + o.turn * o.turn * turned) * g2;
    }
    const double oc = std::cos(r.odometry.heading), os = std::sin(r.odometry.heading);
    r.odometry.position += Vec2(oc * dx - os * dy, os * dx + oc * dy);
    r.odometry.heading = wrapAngle(r.odometry.heading + dh);
  }
};

}  // namespace frob::worlds

// Box2D 2.4 times every phase of Step, and every island's solve, for b2World::GetProfile(), which
// nothing here reads: some 14 gettimeofday calls a step for one robot, 600 for a hundred, about a
// tenth of a one-robot step. libbox2d.so calls its b2Timer through the PLT, so these definitions,
// linked into the program with the simulation, take the place of its own: no clock is read and
// the profile reads zero. Were Box2D linked statically, the duplicate symbols would fail the link
// rather than pass silently.
b2Timer::b2Timer() : m_start_sec(0), m_start_usec(0) {}
void b2Timer::Reset() {}
float b2Timer::GetMilliseconds() const { return 0.0f; }

namespace frob::worlds {

Simulation::Simulation(const WorldDef& world, const SimOptions& options) : impl_(std::make_unique<Impl>(world, options)) {}
Simulation::~Simulation() = default;
Simulation::Simulation(Simulation&&) noexcept = default;
Simulation& Simulation::operator=(Simulation&&) noexcept = default;

void Simulation::sense() {
  Impl& s = *impl_;
  s.robotsMoved = s.centres.size() != s.robots.size();
  s.centres.resize(s.robots.size());
  s.radii.resize(s.robots.size());
  for (std::size_t i = 0; i < s.robots.size(); ++i) {
    const b2Vec2 p = s.robots[i].body->GetPosition();
    const Point2 centre(p.x, p.y);
    s.robotsMoved = s.robotsMoved || !sameBits(centre.x(), s.centres[i].x()) || !sameBits(centre.y(), s.centres[i].y());
    s.centres[i] = centre;
    s.radii[i] = s.robots[i].def.radius;
  }
  if (s.robotsMoved) s.caster.setRobots(s.centres, s.radii, s.reach);
  // Ray casting is read-only on shared state and each robot has its own random stream, so robots
  // may be sensed on any thread in any order with bit-identical results.
  const auto keysNow = std::lower_bound(s.keys.begin(), s.keys.end(), s.steps, [](const auto& k, std::int64_t step) { return k.first < step; });
  const bool odometry = std::exchange(s.odometryPending, false);
  s.workers.run(s.robots.size(), kSenseGrain, [&s, keysNow, odometry](std::size_t begin, std::size_t end) {
    thread_local Impl::SenseScratch scratch;  // kept between steps: allocating it anew cost a robot alone 8%
    for (std::size_t i = begin; i < end; ++i) {
      if (odometry) s.updateOdometry(s.robots[i]);
      s.senseRobot(i, keysNow, scratch);
    }
  });
}

const SensorFrame& Simulation::frame(std::size_t i) const { return impl_->robots.at(i).frame; }

void Simulation::step(std::span<const Wheels> wheels) {
  Impl& s = *impl_;
  FROB_ASSERT(wheels.size() == s.robots.size(), "step() needs one Wheels per robot");
  s.settleOdometry();
  const double dt = s.options.dt;
  for (std::size_t i = 0; i < s.robots.size(); ++i) {
    RobotState& r = s.robots[i];
    r.bumps.clear();
    Wheels w = i < wheels.size() && s.steps * dt >= r.def.drive.startDelay - 1e-9 ? wheels[i] : Wheels{};
    if (!std::isfinite(w.forward) || !std::isfinite(w.turn)) {
      ++r.invalid;
      w = {};
    }
    // Clamp to the speed limits, then approach at bounded acceleration.
    const DriveDef& d = r.def.drive;
    const double forward = std::clamp(w.forward, -d.maxSpeed, d.maxSpeed);
    const double turn = std::clamp(w.turn, -d.maxTurnRate, d.maxTurnRate);
    r.forward += std::clamp(forward - r.forward, -d.acceleration * dt, d.acceleration * dt);
    r.turn += std::clamp(turn - r.turn, -d.turnAcceleration * dt, d.turnAcceleration * dt);
    if (r.slipKick > 0) {
      r.slipForward = r.slipDecay * r.slipForward + r.slipKick * r.slipRng.gaussian();
      r.slipTurn = r.slipDecay * r.slipTurn + r.slipKick * r.slipRng.gaussian();
    }
    const b2Rot& heading = r.body->GetTransform().q;  // Box2D's cosf and sinf of GetAngle(), kept with the body
    r.body->SetLinearVelocity(static_cast<float>(r.forward * (1.0 + r.slipForward)) * b2Vec2(heading.c, heading.s));
    r.body->SetAngularVelocity(static_cast<float>(r.turn * (1.0 + r.slipTurn)));
  }
  s.physics.Step(static_cast<float>(dt), kVelocityIterations, kPositionIterations);
  // Like sensing, odometry reads only its own body and draws from its own random stream, so it
  // may wait for the next sense() and give the same bits.
  s.odometryPending = true;
  ++s.steps;
}

std::uint64_t simulationFingerprint() {
  WorldDef w{.size = {4.0, 2.0}, .walls = {segmentWall({3.5, 0.0}, {3.5, 2.0})}, .robots = {{.start = {.position = Point2(1.0, 1.0)}}}};
  Simulation sim(w);
  Fnv1a h;
  const std::vector<Wheels> wheels{{.forward = 0.5, .turn = 0.2}};
  for (int k = 0; k < 300; ++k) {
    sim.sense();
    for (double s : sim.frame(0).sonar) h.add(s);
    const Pose2 p = sim.truePose(0), o = sim.frame(0).odometry;
    h.add(p.position.x()).add(p.position.y()).add(p.heading).add(o.position.x()).add(o.position.y()).add(o.heading);
    sim.step(wheels);
  }
  return h.value();
}

std::size_t Simulation::robotCount() const { return impl_->robots.size(); }
const RobotSpec& Simulation::spec(std::size_t i) const { return impl_->robots.at(i).spec; }
const RobotDef& Simulation::robot(std::size_t i) const { return impl_->robots.at(i).def; }

std::string Simulation::robotName(std::size_t i) const {
  const std::string& name = robot(i).name;
  if (name.empty()) return "robot" + std::to_string(i);
  for (std::size_t j = 0; j < robotCount(); ++j) {
    if (j != i && robot(j).name == name) return name + "#" + std::to_string(i);
  }
  return name;
}
Pose2 Simulation::truePose(std::size_t i) const { return poseOf(impl_->robots.at(i).body); }
Pose2 Simulation::odometry(std::size_t i) const {
  impl_->settleOdometry();
  return impl_->robots.at(i).odometry;
}
std::size_t Simulation::invalidCommands(std::size_t i) const { return impl_->robots.at(i).invalid; }
bool Simulation::touching(std::size_t i) const {
  const std::vector<int>& pressed = impl_->robots.at(i).pressed;
  return std::any_of(pressed.begin(), pressed.end(), [](int n) { return n > 0; });
}
std::int64_t Simulation::stepCount() const { return impl_->steps; }
double Simulation::time() const { return static_cast<double>(impl_->steps) * impl_->options.dt; }
double Simulation::dt() const { return impl_->options.dt; }
std::uint64_t Simulation::seed() const { return impl_->seed; }
const WorldDef& Simulation::world() const { return impl_->world; }
const std::vector<WallDef>& Simulation::walls() const { return impl_->walls; }

}  // namespace frob::worlds
