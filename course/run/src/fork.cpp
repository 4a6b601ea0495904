#include "frob/run/fork.hpp"

#include "frob/run/format.hpp"

#include <nlohmann/json.hpp>

#include <openssl/evp.h>
#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>

namespace frob::course {

namespace {

// The cells of one CSV line; a quoted cell (a task's name) only at the end, which is not needed.
std::vector<std::string_view> cells(std::string_view line) {
  std::vector<std::string_view> out;
  for (std::size_t at = 0; at <= line.size();) {
    if (at < line.size() && line[at] == '"') break;
    const std::size_t end = std::min(line.find(',', at), line.size());
    out.push_back(line.substr(at, end - at));
    at = end + 1;
  }
  return out;
}

bool number(std::string_view text, double& out) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), out);
  return error == std::errc() && end == text.data() + text.size();
}

class ForkDriver final : public worlds::ControllerDriver {
 public:
  ForkDriver(const ForkPoint& fork, const worlds::Simulation& sim, std::unique_ptr<worlds::ControllerDriver> controllers)
      : fork_(fork), sim_(sim), controllers_(std::move(controllers)) {}

  void decide(const Instant& now, std::span<Wheels> wheels, std::span<Picture> pictures,
              std::vector<std::pair<std::size_t, std::string>>& failed) override {
    const auto k = static_cast<std::size_t>(now.step);
    if (k < fork_.poses.size()) {  // the earlier run's instant: the same world to the last bit, or not this run at all
      for (std::size_t i = 0; i < wheels.size() && !strayed_; ++i) {
        const Pose2 was = fork_.poses[k][i], is = sim_.truePose(i);
        const double d = fork_.tolerance;
        if (std::abs(was.position.x() - is.position.x()) <= d && std::abs(was.position.y() - is.position.y()) <= d &&
            std::abs(was.heading - is.heading) <= d)
          continue;
        strayed_ = true;
        failed.emplace_back(i, format("the run strays from %s at %.2f s: it is not a run of this world and seed (give frob run that run's --world, "
                                      "--seed and --dt)",
                                      fork_.source.c_str(), now.time));
      }
    }
    if (k < fork_.wheels.size()) {
      for (std::size_t i = 0; i < wheels.size(); ++i) wheels[i] = fork_.wheels[k][i];
      return;
    }
    controllers_->decide(now, wheels, pictures, failed);
  }
  Timeline& timeline(std::size_t i) override { return controllers_->timeline(i); }
  bool finished(std::size_t i) const override { return controllers_->finished(i); }

 private:
  const ForkPoint& fork_;
  const worlds::Simulation& sim_;
  std::unique_ptr<worlds::ControllerDriver> controllers_;
  bool strayed_ = false;
};

// The run a viewer page keeps (run_page.cpp): JSON, deflated, in base64, in its run-data script.
Result<nlohmann::json> pageData(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return Status::failure("--from: cannot read the page '" + file + "' (write one with frob run --html)");
  const std::string page{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::string open = "id=\"run-data\">";
  const std::size_t at = page.find(open), end = at == std::string::npos ? at : page.find("</script>", at);
  if (end == std::string::npos) return Status::failure("--from: " + file + " is not a run viewer page of frob run (frob run --html)");
  std::string text = page.substr(at + open.size(), end - at - open.size());
  std::erase_if(text, [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; });
  if (text.empty() || text.size() % 4 != 0) return Status::failure("--from: " + file + ": its run data is not base64");
  std::string packed(text.size() / 4 * 3, '\0');
  const int n = EVP_DecodeBlock(reinterpret_cast<unsigned char*>(packed.data()), reinterpret_cast<const unsigned char*>(text.data()),
                                static_cast<int>(text.size()));
  if (n < 0) return Status::failure("--from: " + file + ": its run data is not base64");
  packed.resize(static_cast<std::size_t>(n) - static_cast<std::size_t>(std::count(text.end() - 2, text.end(), '=')));
  z_stream z{};
  std::string json;
  bool inflated = inflateInit(&z) == Z_OK;
  z.next_in = reinterpret_cast<Bytef*>(packed.data());
  z.avail_in = static_cast<uInt>(packed.size());
  for (int status = Z_OK; inflated && status == Z_OK;) {
    char chunk[1 << 16];
    z.next_out = reinterpret_cast<Bytef*>(chunk);
    z.avail_out = sizeof chunk;
    status = inflate(&z, Z_NO_FLUSH);
    json.append(chunk, sizeof chunk - z.avail_out);
    inflated = status == Z_OK || status == Z_STREAM_END;
  }
  inflateEnd(&z);
  nlohmann::json doc = inflated ? nlohmann::json::parse(json, nullptr, false) : nlohmann::json();
  if (!inflated || doc.is_discarded()) return Status::failure("--from: " + file + ": its run data cannot be read");
  return doc;
}

// A page's run up to the fork's instant: poses to the millimetre (as the page keeps them), wheels to the bit.
Result<ForkPoint> fromPage(ForkPoint f, double dt) {
  Result<nlohmann::json> data = pageData(f.source);
  if (!data) return data.status();
  const nlohmann::json& doc = data.value();
  try {
    const double pageDt = doc.at("dt").get<double>();
    if (std::abs(pageDt - dt) > 1e-12) {
      return Status::failure(format("--from: %s is a run with steps of %g s: give --dt %g", f.source.c_str(), pageDt, pageDt));
    }
    const auto samples = doc.at("samples").get<std::size_t>(), steps = static_cast<std::size_t>(std::llround(f.at / dt));
    if (doc.at("t0").get<double>() != 0.0 || steps >= samples) {
      return Status::failure(
          format("--from: %s has its run up to %.2f s, not to %.2f s", f.source.c_str(), static_cast<double>(samples - 1) * dt, f.at));
    }
    f.poses.assign(steps + 1, {}), f.wheels.assign(steps, {});
    for (const nlohmann::json& r : doc.at("robots")) {
      const nlohmann::json &q = r.at("q"), &wheels = r.at("wheels");
      double x = 0, y = 0, h = 0;  // whole thousandths, each the difference from the one before
      for (std::size_t k = 0; k <= steps; ++k) {
        x += q.at("x").at(k).get<double>(), y += q.at("y").at(k).get<double>(), h += q.at("h").at(k).get<double>();
        f.poses[k].push_back(Pose2{Point2(x / 1000, y / 1000), h / 1000});
        if (k < steps) f.wheels[k].push_back(Wheels{wheels.at(k).at(0).get<double>(), wheels.at(k).at(1).get<double>()});
      }
    }
  } catch (const nlohmann::json::exception&) {
    return Status::failure("--from: " + f.source + ": its run data is not that of a run viewer page of this frob");
  }
  f.tolerance = 0.0005 + 1e-9;  // half a thousandth, as the page rounds
  return f;
}

}  // namespace

Result<ForkPoint> readForkPoint(const std::string& spec, double dt) {
  const std::size_t hash = spec.rfind("#t=");
  ForkPoint f{.source = spec.substr(0, hash)};
  if (hash == std::string::npos || !number(std::string_view(spec).substr(hash + 3), f.at) || !(f.at >= 0)) {
    return Status::failure("--from " + spec + ": give an earlier run's page or trace and an instant of it, e.g. run.html#t=12.5");
  }
  if (f.source.ends_with(".html")) return fromPage(std::move(f), dt);
  std::ifstream in(f.source);
  if (!in) return Status::failure("--from: cannot read the trace '" + f.source + "' (write one with frob run --trace)");
  const auto bad = [&](std::size_t line, const std::string& why) {
    return Status::failure(format("--from: %s:%zu: %s", f.source.c_str(), line, why.c_str()));
  };
  std::string line;
  if (!std::getline(in, line) || !line.starts_with("time,robot,true_x,true_y,true_heading,odom_x,odom_y,odom_heading,forward,turn,")) {
    return bad(1, "not a trace of frob run (its first line names time, robot, true_x, ...)");
  }
  const auto steps = static_cast<std::size_t>(std::llround(f.at / dt));
  for (std::size_t n = 2; std::getline(in, line); ++n) {
    const std::vector<std::string_view> c = cells(line);
    double v[10];
    for (std::size_t j = 0; j < 10; ++j) {
      if (j >= c.size() || !number(c[j], v[j])) return bad(n, "not a row of numbers where a trace has them");
    }
    const auto k = static_cast<std::size_t>(std::llround(v[0] / dt)), robot = static_cast<std::size_t>(v[1]);
    if (std::abs(static_cast<double>(k) * dt - v[0]) > 1e-6 || v[1] != static_cast<double>(robot))
      return bad(n, "a time or robot that is not a step's");
    if (k > steps) break;
    if (k >= f.poses.size()) f.poses.resize(k + 1), f.wheels.resize(k + 1);
    if (robot != f.poses[k].size()) return bad(n, "rows out of order (each step's robots in turn)");
    f.poses[k].push_back(Pose2{Point2(v[2], v[3]), v[4]});
    f.wheels[k].push_back(Wheels{v[8], v[9]});
  }
  if (f.poses.size() != steps + 1) {
    return Status::failure(format("--from: %s has its run up to %.2f s, not to %.2f s", f.source.c_str(),
                                  f.poses.empty() ? 0.0 : static_cast<double>(f.poses.size() - 1) * dt, f.at));
  }
  f.wheels.pop_back();  // the controllers decide at the instant itself
  return f;
}

worlds::DriverFactory forkedAt(const ForkPoint& fork, worlds::DriverFactory controllers) {
  return [&fork, controllers = std::move(controllers)](const worlds::Simulation& sim) -> std::unique_ptr<worlds::ControllerDriver> {
    return std::make_unique<ForkDriver>(fork, sim, controllers(sim));
  };
}

}  // namespace frob::course
