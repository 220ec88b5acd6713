// cgcm-analytic: the closed-form adhesive contact models (Hertz, JKR, DMT,
// Maugis-Dugdale) in the Johnson-Greenwood normalisation, their subsurface
// stress, their pull-off points, the CGCM <-> M-D mapping, the fit of λ to
// a computed CGCM load curve, and the numerical Lennard-Jones sphere
// (ljsphere) whose pull-off force at a finite Tabor parameter is the
// reference between them; beyond the sphere, the JKR and Maugis-Dugdale
// cylinders, Kendall's peel and the flat punch. Every subcommand writes CSV
// with a header line to stdout or to --output FILE.
//
// Exit codes: 0 success; 2 bad arguments or input (message on stderr naming
// the option and the allowed values); 1 numerical failure.
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cgcm/analytic/CgcmMapping.hpp"
#include "cgcm/analytic/Cylinder.hpp"
#include "cgcm/analytic/FlatPunch.hpp"
#include "cgcm/analytic/LennardJonesSphere.hpp"
#include "cgcm/analytic/LoadCurveFit.hpp"
#include "cgcm/analytic/MaugisDugdale.hpp"
#include "cgcm/analytic/Models.hpp"
#include "cgcm/analytic/Peel.hpp"
#include "cgcm/analytic/Pressure.hpp"
#include "cgcm/analytic/PullOff.hpp"
#include "cgcm/analytic/SubsurfaceStress.hpp"
#include "cgcm/core/Error.hpp"

namespace {

using cgcm::Real;
namespace an = cgcm::analytic;

constexpr const char* kProgram = "cgcm-analytic";

/// Bad command line: reported with the subcommand's usage, exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Args;

struct OptionSpec {
  std::string name;  // without the leading "--"
  bool takesValue;
  std::string help;
};

struct Command {
  std::string name;
  std::string summary;
  std::string details;
  std::vector<OptionSpec> options;
  std::function<void(Args&, std::ostream&)> run;
};

const std::string kModelOptionsHelp =
    "  --model M        hertz, jkr, dmt or md (required)\n"
    "  --lambda L       Maugis-Dugdale transition parameter (41), required for md\n"
    "                   and only for md; 1e-3 <= L <= 1e3\n";
const std::string kCgcmOptionsHelp =
    "  --gammaL G --gammaW G --nu V\n"
    "                   optional, all three or none: also write the columns in CGCM\n"
    "                   normalisation (R0 = Y = 1) through the factors of `map`\n";
const std::string kCommonHelp =
    "  --output FILE    write the CSV to FILE instead of stdout\n"
    "  --help           this text\n";

std::string usageOf(const Command& c) {
  std::ostringstream out;
  out << "usage: " << kProgram << " " << c.name << " [options]\n\n" << c.summary << "\n\n"
      << c.details;
  return out.str();
}

// The options of one command. Not Teuchos::CommandLineProcessor: measured on
// Trilinos 13.2, it takes "--lambda=1abc" as 1 and "--n=2.7" as 2 without a
// word, lets a repeated option win silently, accepts only "--name=value"
// (the "--name value" of every script and document here fails) and aborts
// with an uncaught exception on "--lambda=abc". This parser rejects all of
// these with a message naming the option.
class Args {
 public:
  Args(const Command& cmd, const std::vector<std::string>& argv) : cmd_(cmd) {
    for (std::size_t i = 0; i < argv.size(); ++i) {
      const std::string& arg = argv[i];
      if (arg.rfind("--", 0) != 0 || arg.size() == 2) {
        throw UsageError("unexpected argument '" + arg + "' (options start with --)");
      }
      std::string name = arg.substr(2);
      std::optional<std::string> inlineValue;
      if (const auto eq = name.find('='); eq != std::string::npos) {
        inlineValue = name.substr(eq + 1);
        name = name.substr(0, eq);
      }
      const OptionSpec* spec = find(name);
      if (!spec) throw UsageError("unknown option --" + name + " (allowed: " + allowed() + ")");
      if (values_.count(name)) throw UsageError("option --" + name + " given twice");
      if (spec->takesValue) {
        if (inlineValue) {
          values_[name] = *inlineValue;
        } else {
          if (i + 1 >= argv.size()) throw UsageError("option --" + name + " needs a value");
          values_[name] = argv[++i];
        }
      } else {
        if (inlineValue) throw UsageError("option --" + name + " takes no value");
        values_[name] = "";
      }
    }
  }

  bool has(const std::string& name) const { return values_.count(name) != 0; }

  std::string text(const std::string& name) const {
    const auto it = values_.find(name);
    if (it == values_.end()) throw UsageError("missing required option --" + name);
    return it->second;
  }

  /// A finite number in [lo, hi].
  Real real(const std::string& name, Real lo, Real hi, const std::string& range) const {
    const std::string s = text(name);
    char* end = nullptr;
    errno = 0;
    const Real v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v)) {
      throw UsageError("option --" + name + ": '" + s + "' is not a finite number");
    }
    if (!(v >= lo && v <= hi)) {
      throw UsageError("option --" + name + ": " + s + " is out of range (allowed: " + range + ")");
    }
    return v;
  }
  Real real(const std::string& name, Real lo, Real hi, const std::string& range, Real dflt) const {
    return has(name) ? real(name, lo, hi, range) : dflt;
  }

  long integer(const std::string& name, long lo, long hi) const {
    const std::string s = text(name);
    char* end = nullptr;
    errno = 0;
    const long v = std::strtol(s.c_str(), &end, 10);
    if (s.empty() || *end != '\0' || errno == ERANGE) {
      throw UsageError("option --" + name + ": '" + s + "' is not an integer");
    }
    if (v < lo || v > hi) {
      throw UsageError("option --" + name + ": " + s + " is out of range (allowed: " +
                       std::to_string(lo) + " to " + std::to_string(hi) + ")");
    }
    return v;
  }
  long integer(const std::string& name, long lo, long hi, long dflt) const {
    return has(name) ? integer(name, lo, hi) : dflt;
  }

 private:
  const OptionSpec* find(const std::string& name) const {
    for (const auto& o : cmd_.options) {
      if (o.name == name) return &o;
    }
    return nullptr;
  }
  std::string allowed() const {
    std::string s;
    for (const auto& o : cmd_.options) s += (s.empty() ? "--" : ", --") + o.name;
    return s;
  }
  const Command& cmd_;
  std::map<std::string, std::string> values_;
};

// ---- shared option groups ------------------------------------------------

const std::vector<OptionSpec> kModelOptions = {{"model", true, ""}, {"lambda", true, ""}};
const std::vector<OptionSpec> kCgcmOptions = {
    {"gammaL", true, ""}, {"gammaW", true, ""}, {"nu", true, ""}};
const std::vector<OptionSpec> kCommonOptions = {{"output", true, ""}, {"help", false, ""}};

std::vector<OptionSpec> join(std::initializer_list<std::vector<OptionSpec>> groups) {
  std::vector<OptionSpec> out;
  for (const auto& g : groups) out.insert(out.end(), g.begin(), g.end());
  return out;
}

an::ContactModel modelFrom(const Args& args) {
  const std::string name = args.text("model");
  an::Model kind;
  try {
    kind = an::parseModel(name);
  } catch (const cgcm::InputError&) {
    throw UsageError("option --model: unknown model '" + name +
                     "' (allowed: " + std::string(an::kModelNames) + ")");
  }
  std::optional<Real> lambda;
  if (args.has("lambda")) {
    if (kind != an::Model::MaugisDugdale) {
      throw UsageError("option --lambda applies only to --model md");
    }
    lambda = args.real("lambda", an::kLambdaMin, an::kLambdaMax, "1e-3 <= lambda <= 1e3");
  } else if (kind == an::Model::MaugisDugdale) {
    throw UsageError("--model md needs --lambda (1e-3 <= lambda <= 1e3)");
  }
  return an::ContactModel::make(kind, lambda);
}

std::optional<an::CgcmMapping> mappingFrom(const Args& args, bool required) {
  const int given = args.has("gammaL") + args.has("gammaW") + args.has("nu");
  if (given == 0 && !required) return std::nullopt;
  if (given != 3) {
    throw UsageError("options --gammaL, --gammaW and --nu go together (all three are needed)");
  }
  const Real big = 1e300;
  const Real gL = args.real("gammaL", 0, big, "gammaL > 0");
  const Real gW = args.real("gammaW", 0, big, "gammaW > 0");
  const Real nu = args.real("nu", -1, 0.5, "-1 < nu < 0.5");
  if (gL <= 0) throw UsageError("option --gammaL: must be > 0");
  if (gW <= 0) throw UsageError("option --gammaW: must be > 0");
  if (nu <= -1 || nu >= 0.5) throw UsageError("option --nu: allowed: -1 < nu < 0.5");
  return an::cgcmMapping(gL, gW, nu);
}

/// Formats numbers with 12 significant digits (inf/-inf/nan as printf does).
std::string num(Real v) {
  if (v == 0) v = 0;  // print −0 as 0
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  return buf;
}

// ---- subcommands -----------------------------------------------------------

void runCurve(Args& args, std::ostream& out) {
  const an::ContactModel model = modelFrom(args);
  const auto map = mappingFrom(args, false);
  const Real aMin = args.real("a-min", 1e-12, 1e6, "0 < a-min <= 1e6", 1e-3);
  const Real aMax = args.real("a-max", 1e-12, 1e6, "0 < a-max <= 1e6", 3.0);
  if (!(aMax > aMin)) throw UsageError("option --a-max must exceed --a-min");
  const long n = args.integer("points", 2, 10000000, 300);
  out << "a,P,delta" << (map ? ",a_cgcm,P_cgcm,u_cgcm" : "") << "\n";
  Real sGuess = -1;
  for (long i = 0; i < n; ++i) {
    const Real a = aMin + (aMax - aMin) * static_cast<Real>(i) / static_cast<Real>(n - 1);
    an::CurvePoint p;
    if (model.kind() == an::Model::MaugisDugdale) {
      const an::MdSolution sol = an::solveMaugisDugdale(model.lambda(), a, sGuess);
      sGuess = sol.s;
      p = {a, sol.load, sol.approach};
    } else {
      p = model.at(a);
    }
    out << num(p.a) << "," << num(p.load) << "," << num(p.approach);
    if (map) out << "," << num(map->fa * p.a) << "," << num(map->fF * p.load) << "," << num(map->fdelta * p.approach);
    out << "\n";
  }
}

void runPressure(Args& args, std::ostream& out) {
  const an::ContactModel model = modelFrom(args);
  const auto map = mappingFrom(args, false);
  const Real a = args.real("a", 1e-12, 1e6, "0 < a <= 1e6");
  const an::PressureProfile p(model, a);
  const Real m = p.outerRadius() / a;
  const Real rmax = args.real("rmax", 0, 1e6, "0 < rmax <= 1e6 (multiples of a)",
                              std::fmax(1.5, 1.25 * m));
  if (rmax <= 0) throw UsageError("option --rmax must be > 0");
  const long n = args.integer("points", 2, 10000000, 301);
  out << "r_over_a,p" << (map ? ",r_cgcm,p_cgcm" : "") << "\n";
  for (long i = 0; i < n; ++i) {
    const Real x = rmax * static_cast<Real>(i) / static_cast<Real>(n - 1);
    const Real v = p.atRelative(x);
    out << num(x) << "," << num(v);
    if (map) out << "," << num(map->fa * x * a) << "," << num(map->fsigma * v);
    out << "\n";
  }
}

void runStress(Args& args, std::ostream& out) {
  const an::ContactModel model = modelFrom(args);
  const auto map = mappingFrom(args, false);
  const Real a = args.real("a", 1e-12, 1e6, "0 < a <= 1e6");
  const std::string grid = args.text("grid");
  long nr = 0, nz = 0;
  {
    char* end = nullptr;
    errno = 0;
    nr = std::strtol(grid.c_str(), &end, 10);
    const bool okFirst = end != grid.c_str() && *end == ',';
    const char* second = okFirst ? end + 1 : end;
    nz = okFirst ? std::strtol(second, &end, 10) : 0;
    if (!okFirst || end == second || *end != '\0' || errno == ERANGE || nr < 2 || nz < 2 ||
        nr > 100000 || nz > 100000) {
      throw UsageError("option --grid: '" + grid +
                       "' is not NR,NZ (two integers, 2 to 100000, e.g. --grid 200,200)");
    }
  }
  const Real rmax = args.real("rmax", 0, 1e6, "0 < rmax <= 1e6 (multiples of a)", 2.0);
  const Real zmax = args.real("zmax", 0, 1e6, "0 < zmax <= 1e6 (multiples of a)", 2.0);
  if (rmax <= 0) throw UsageError("option --rmax must be > 0");
  if (zmax <= 0) throw UsageError("option --zmax must be > 0");
  const long threads = args.integer("threads", 1, 256, 1);
  an::StressOptions opt;
  opt.relTol = args.real("tol", 1e-14, 1e-2, "1e-14 <= tol <= 1e-2", opt.relTol);
  const an::PressureProfile p(model, a);
  std::vector<Real> r(nr), z(nz);
  for (long i = 0; i < nr; ++i) r[i] = rmax * a * static_cast<Real>(i) / static_cast<Real>(nr - 1);
  for (long j = 0; j < nz; ++j) z[j] = zmax * a * static_cast<Real>(j) / static_cast<Real>(nz - 1);
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<Real> s = an::sigmaZGrid(p, r, z, opt, static_cast<int>(threads));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cerr << kProgram << " stress: " << nr << " x " << nz << " points in " << seconds << " s\n";
  out << "r,z,sigma_z" << (map ? ",r_cgcm,z_cgcm,sigma_z_cgcm" : "") << "\n";
  for (long j = 0; j < nz; ++j) {
    for (long i = 0; i < nr; ++i) {
      const Real v = s[static_cast<std::size_t>(j * nr + i)];
      out << num(r[i]) << "," << num(z[j]) << "," << num(v);
      if (map) out << "," << num(map->fa * r[i]) << "," << num(map->fa * z[j]) << "," << num(map->fsigma * v);
      out << "\n";
    }
  }
}

void runPullOff(Args& args, std::ostream& out) {
  const an::ContactModel model = modelFrom(args);
  const an::PullOff p = an::pullOff(model);
  if (!p.adhesive) {
    std::cerr << kProgram << " pulloff: hertz has no adhesion and no pull-off; "
              << "both rows report P = 0 at a = 0\n";
  } else if (!p.displacementJump) {
    std::cerr << kProgram << " pulloff: " << model.describe()
              << ": no jump under displacement control (d delta/d a > 0 for all a > 0); "
              << "the displacement row is the end of the contact branch, a -> 0\n";
  }
  out << "control,P,a,delta\n";
  out << "load," << num(p.loadControl.load) << "," << num(p.loadControl.a) << ","
      << num(p.loadControl.approach) << "\n";
  out << "displacement," << num(p.displacementControl.load) << "," << num(p.displacementControl.a)
      << "," << num(p.displacementControl.approach) << "\n";
}

/// Three material options that go together (all or none); nullopt when none.
std::optional<std::array<Real, 3>> physicalFrom(const Args& args, const std::array<const char*, 3>& names) {
  const int given = args.has(names[0]) + args.has(names[1]) + args.has(names[2]);
  if (given == 0) return std::nullopt;
  const std::string list = std::string("--") + names[0] + ", --" + names[1] + " and --" + names[2];
  if (given != 3) throw UsageError("options " + list + " go together (all three are needed)");
  std::array<Real, 3> v{};
  for (int i = 0; i < 3; ++i) {
    v[i] = args.real(names[i], 0, 1e300, std::string(names[i]) + " > 0");
    if (v[i] <= 0) throw UsageError(std::string("option --") + names[i] + ": must be > 0");
  }
  return v;
}

void runCylinder(Args& args, std::ostream& out) {
  const std::string name = args.text("model");
  if (name != "hertz" && name != "jkr" && name != "md") {
    throw UsageError("option --model: '" + name + "' is not a cylinder model (allowed: hertz, jkr, md;" +
                     " the cylinder has no DMT limit with a finite force: use md with a small lambda)");
  }
  const bool md = name == "md";
  Real lambda = 0;
  if (args.has("lambda")) {
    if (!md) throw UsageError("option --lambda applies only to --model md");
    lambda = args.real("lambda", an::kLambdaMin, an::kLambdaMax, "1e-3 <= lambda <= 1e3");
  } else if (md) {
    throw UsageError("--model md needs --lambda (1e-3 <= lambda <= 1e3)");
  }
  const auto phys = physicalFrom(args, {"Estar", "w", "R"});
  std::optional<an::CylinderScales> sc;
  if (phys) sc = an::CylinderScales::from((*phys)[1], (*phys)[2], (*phys)[0]);
  auto row = [&](const an::CylinderPoint& p) {
    out << num(p.a) << "," << num(p.load) << "," << num(p.c);
    if (sc) out << "," << num(p.a * sc->length) << "," << num(p.load * sc->force) << "," << num(p.c * sc->length);
    out << "\n";
  };
  out << "a,P,c" << (sc ? ",a_phys,P_phys,c_phys" : "") << "\n";
  if (args.has("pulloff")) {
    for (const char* o : {"a-min", "a-max", "points"}) {
      if (args.has(o)) throw UsageError(std::string("option --") + o + " does not apply with --pulloff");
    }
    if (name == "hertz") {
      std::cerr << kProgram << " cylinder: hertz has no adhesion and no pull-off; the row reports P = 0 at a = 0\n";
      row({0, 0, 0});
    } else {
      row(md ? an::mdCylinderPullOff(lambda) : an::jkrCylinderPullOff());
    }
    return;
  }
  const Real aMin = args.real("a-min", 1e-12, 1e6, "0 < a-min <= 1e6", 1e-3);
  const Real aMax = args.real("a-max", 1e-12, 1e6, "0 < a-max <= 1e6", 3.0);
  if (!(aMax > aMin)) throw UsageError("option --a-max must exceed --a-min");
  const long n = args.integer("points", 2, 10000000, 300);
  Real sGuess = -1;
  for (long i = 0; i < n; ++i) {
    const Real a = aMin + (aMax - aMin) * static_cast<Real>(i) / static_cast<Real>(n - 1);
    if (md) {
      const an::MdCylinderSolution sol = an::solveMdCylinder(lambda, a, sGuess);
      sGuess = sol.s;
      row({a, sol.load, sol.m * a});
    } else if (name == "jkr") {
      row(an::jkrCylinder(a));
    } else {
      row({a, 0.25 * cgcm::kPi * a * a, a});
    }
  }
}

void runPeel(Args& args, std::ostream& out) {
  const Real eps = args.real("epsilon", 0, 1e300, "epsilon = w/(E_t h) >= 0");
  std::vector<Real> angles;
  if (args.has("theta")) {
    for (const char* o : {"theta-min", "theta-max", "points"}) {
      if (args.has(o)) throw UsageError(std::string("option --") + o + " does not apply with --theta");
    }
    angles.push_back(args.real("theta", 0, 180, "0 <= theta <= 180 (degrees)"));
  } else {
    const Real lo = args.real("theta-min", 0, 180, "0 <= theta-min <= 180 (degrees)", 0.0);
    const Real hi = args.real("theta-max", 0, 180, "0 <= theta-max <= 180 (degrees)", 180.0);
    if (!(hi > lo)) throw UsageError("option --theta-max must exceed --theta-min");
    const long n = args.integer("points", 2, 10000000, 181);
    for (long i = 0; i < n; ++i) angles.push_back(lo + (hi - lo) * static_cast<Real>(i) / static_cast<Real>(n - 1));
  }
  if (eps == 0 && angles.front() == 0) {
    throw UsageError("theta = 0 needs --epsilon > 0 (an inextensible strip cannot be peeled at 0 degrees)");
  }
  out << "theta_deg,F_over_bw,inextensible_F_over_bw,held_end_F_over_bw\n";
  for (Real deg : angles) {
    const Real theta = deg * cgcm::kPi / 180;
    const Real inf = std::numeric_limits<Real>::infinity();
    const Real inext = deg > 0 ? an::inextensiblePeelForce(theta) : inf;
    const Real held = deg > 0 ? an::heldEndPeelForce(theta, eps) : inf;
    out << num(deg) << "," << num(an::kendallPeelForce(theta, eps)) << "," << num(inext) << "," << num(held) << "\n";
  }
}

void runPunch(Args& args, std::ostream& out) {
  an::PunchGeometry geometry;
  const std::string g = args.text("geometry");
  try {
    geometry = an::parsePunchGeometry(g);
  } catch (const cgcm::InputError&) {
    throw UsageError("option --geometry: unknown geometry '" + g + "' (allowed: axisymmetric, strip)");
  }
  const Real lo = args.real("a-min", 1e-12, 1e12, "0 < a-min <= 1e12 (multiples of a_cr)", 1e-2);
  const Real hi = args.real("a-max", 1e-12, 1e12, "0 < a-max <= 1e12 (multiples of a_cr)", 1e2);
  if (!(hi > lo)) throw UsageError("option --a-max must exceed --a-min");
  const long n = args.integer("points", 2, 10000000, 41);
  const auto phys = physicalFrom(args, {"Estar", "w", "sigma-max"});
  std::optional<an::FlatPunch> punch;
  if (phys) {
    punch.emplace(geometry, (*phys)[0], (*phys)[1], (*phys)[2]);
    std::cerr << kProgram << " punch: critical size a_cr = " << num(punch->criticalSize()) << "\n";
  }
  out << "a_over_acr,kendall_over_strength" << (punch ? ",a,F_kendall,F_strength" : "") << "\n";
  for (long i = 0; i < n; ++i) {
    const Real x = lo * std::pow(hi / lo, static_cast<Real>(i) / static_cast<Real>(n - 1));
    out << num(x) << "," << num(1 / std::sqrt(x));
    if (punch) {
      const Real a = x * punch->criticalSize();
      out << "," << num(a) << "," << num(punch->kendallForce(a)) << "," << num(punch->strengthForce(a));
    }
    out << "\n";
  }
}

void runMap(Args& args, std::ostream& out) {
  const an::CgcmMapping m = *mappingFrom(args, true);
  out << "gammaL,gammaW,nu,f_w,f_E,f_F,f_a,f_delta,f_sigma,w,sigma_max,lambda_theory,mu_tabor\n";
  out << num(m.gammaL) << "," << num(m.gammaW) << "," << num(m.nu) << "," << num(m.fw) << ","
      << num(m.fE) << "," << num(m.fF) << "," << num(m.fa) << "," << num(m.fdelta) << ","
      << num(m.fsigma) << "," << num(m.workOfAdhesion) << "," << num(m.sigmaMax) << ","
      << num(m.lambdaTheory) << "," << num(m.muTabor) << "\n";
}

void runFit(Args& args, std::ostream& out) {
  const an::CgcmMapping map = *mappingFrom(args, true);
  const std::string path = args.text("curve");
  an::FitOptions opt;
  const Real big = 1e300;
  opt.lambdaMin = args.real("lambda-min", an::kLambdaMin, an::kLambdaMax, "1e-3 <= lambda-min <= 1e3", an::kLambdaMin);
  opt.lambdaMax = args.real("lambda-max", an::kLambdaMin, an::kLambdaMax, "1e-3 <= lambda-max <= 1e3", an::kLambdaMax);
  if (!(opt.lambdaMax > opt.lambdaMin)) throw UsageError("option --lambda-max must exceed --lambda-min");
  opt.fitOffset = args.has("fit-offset");
  opt.offset = args.real("offset", -big, big, "a finite number", 0.0);
  if (args.has("offset-bound")) {
    if (!opt.fitOffset) throw UsageError("option --offset-bound needs --fit-offset");
    opt.offsetBound = args.real("offset-bound", 0, big, "offset-bound > 0");
    if (*opt.offsetBound <= 0) throw UsageError("option --offset-bound must be > 0");
  }
  if (args.has("u-min")) opt.uMin = args.real("u-min", -big, big, "a finite number");
  if (args.has("u-max")) opt.uMax = args.real("u-max", -big, big, "a finite number");
  const std::string uCol = args.has("u-column") ? args.text("u-column") : "u";
  const std::string pCol = args.has("P-column") ? args.text("P-column") : "P";
  const an::LoadCurve curve = an::readLoadCurveCsv(path, uCol, pCol);
  const an::FitResult r = an::fitMaugisDugdale(curve, map, opt);
  if (r.atBound) {
    std::cerr << kProgram << " fit: warning: the best lambda lies at the end of the search range ["
              << opt.lambdaMin << ", " << opt.lambdaMax << "]\n";
  }
  out << "lambda,offset,rms_residual,max_abs_residual,rms_relative,points,u_from,u_to,lambda_theory\n";
  out << num(r.lambda) << "," << num(r.offset) << "," << num(r.rms) << "," << num(r.maxAbs) << ","
      << num(r.rmsRelative) << "," << r.points << "," << num(r.uFrom) << "," << num(r.uTo) << ","
      << num(map.lambdaTheory) << "\n";
}

void runLjSphere(Args& args, std::ostream& out) {
  const Real mu = args.real("mu", 1e-3, 1e3, "1e-3 <= mu <= 1e3");
  an::LjSphereOptions opt;
  opt.rings = static_cast<int>(args.integer("rings", 50, 5000, opt.rings));
  opt.deltaStart = args.real("delta-start", 0, 1e6, "0 <= delta-start <= 1e6", 0.0);
  const auto t0 = std::chrono::steady_clock::now();
  const an::LjSphereCurve c = an::ljSphereRetraction(mu, opt);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cerr << kProgram << " ljsphere: mu = " << mu << ", " << c.rings << " rings, "
            << c.retraction.size() << " points, " << c.remeshes << " remeshes, "
            << c.factorisations << " Jacobian factorisations in " << seconds << " s\n";
  if (!c.reachedEnd) {
    std::cerr << kProgram << " ljsphere: warning: the branch did not reach its end within "
              << opt.maxSteps << " steps\n";
  }
  if (c.minimumInterior && !c.refined) {
    std::cerr << kProgram << " ljsphere: note: the refinement of the minimum failed; P_min is "
              << "the smallest sample of the branch\n";
  }
  if (!c.minimumInterior) {
    std::cerr << kProgram << " ljsphere: warning: the minimum force is at an end of the "
              << "computed branch (not bracketed)\n";
  }
  if (args.has("pulloff")) {
    out << "mu,P_min,delta_at_min,contact_radius_at_min,peak_radius_at_min\n";
    out << num(mu) << "," << num(c.minimumLoad) << "," << num(c.deltaAtMinimum) << ","
        << num(c.contactRadiusAtMinimum) << "," << num(c.peakRadiusAtMinimum) << "\n";
    return;
  }
  out << "delta_over_z0,P_over_piwR,contact_radius,peak_radius\n";
  for (const auto& p : c.retraction) {
    out << num(p.delta) << "," << num(p.load) << "," << num(p.contactRadius) << ","
        << num(p.peakRadius) << "\n";
  }
}

std::vector<Command> commands() {
  return {
      {"curve", "Equilibrium curve of a model: columns a, P, delta (normalised by (36)).",
       "options:\n" + kModelOptionsHelp +
           "  --a-min A        smallest contact radius (default 1e-3)\n"
           "  --a-max A        largest contact radius (default 3)\n"
           "  --points N       number of radii, evenly spaced (default 300)\n" +
           kCgcmOptionsHelp + "                   (columns a_cgcm, P_cgcm, u_cgcm)\n" + kCommonHelp +
           "\nexample: cgcm-analytic curve --model md --lambda 0.25 --a-max 2\n",
       join({kModelOptions, kCgcmOptions, kCommonOptions,
             {{"a-min", true, ""}, {"a-max", true, ""}, {"points", true, ""}}}),
       runCurve},
      {"pressure", "Contact pressure p(r) at contact radius a: columns r_over_a, p.",
       "options:\n" + kModelOptionsHelp +
           "  --a A            contact radius (normalised, required)\n"
           "  --rmax X         largest r/a (default 1.5, or 1.25 m for md so that the\n"
           "                   adhesive zone a <= r <= m a shows)\n"
           "  --points N       number of radii from 0 to rmax (default 301)\n" +
           kCgcmOptionsHelp + "                   (columns r_cgcm, p_cgcm)\n" + kCommonHelp +
           "\nJKR gives p = -inf at r = a. DMT gives the Hertz pressure: its adhesive\n"
           "force acts outside the contact with vanishing stress.\n"
           "\nexample: cgcm-analytic pressure --model md --lambda 1 --a 1\n",
       join({kModelOptions, kCgcmOptions, kCommonOptions, {{"a", true, ""}, {"rmax", true, ""}, {"points", true, ""}}}),
       runPressure},
      {"stress", "Subsurface stress sigma_z(r, z) from (46) on a grid: columns r, z, sigma_z.",
       "options:\n" + kModelOptionsHelp +
           "  --a A            contact radius (normalised, required)\n"
           "  --grid NR,NZ     grid size (required), r from 0 to rmax*a, z from 0 to zmax*a\n"
           "  --rmax X         (default 2) and --zmax X (default 2), multiples of a\n"
           "  --threads N      worker threads (default 1)\n"
           "  --tol T          tolerance of each sigma_z relative to the pressure scale\n"
           "                   (default 1e-9)\n" +
           kCgcmOptionsHelp + "                   (columns r_cgcm, z_cgcm, sigma_z_cgcm)\n" + kCommonHelp +
           "\nr and z are normalised like a; sigma_z like p (compression negative);\n"
           "sigma_z(r, 0) = -p(r). The run time is reported on stderr.\n"
           "\nexample: cgcm-analytic stress --model md --lambda 1 --a 1 --grid 200,200\n",
       join({kModelOptions, kCgcmOptions, kCommonOptions,
             {{"a", true, ""}, {"grid", true, ""}, {"rmax", true, ""}, {"zmax", true, ""},
              {"threads", true, ""}, {"tol", true, ""}}}),
       runStress},
      {"pulloff", "Load- and displacement-control pull-off points: control, P, a, delta.",
       "options:\n" + kModelOptionsHelp + kCommonHelp +
           "\nRow `load`: the minimum of P(a). Row `displacement`: the point where\n"
           "d delta/d a = 0 (fixed grips). Hertz has no pull-off (both rows P = 0 at\n"
           "a = 0). For md with lambda below about 0.938 delta(a) is monotone, the\n"
           "contact shrinks to a = 0 without a jump, and the displacement row is that\n"
           "end point (a note goes to stderr).\n"
           "\nexample: cgcm-analytic pulloff --model md --lambda 1\n",
       join({kModelOptions, kCommonOptions}), runPullOff},
      {"map", "CGCM <-> M-D normalisation factors (48)-(53), theoretical lambda, Tabor mu.",
       "options:\n"
       "  --gammaL G       gammaL = R0/r0 (plain, not barred; required)\n"
       "  --gammaW G       gammaW = Y/(beta0^2 r0^3 eps) (plain; required)\n"
       "  --nu V           Poisson ratio, -1 < nu < 0.5 (required)\n" +
           kCommonHelp +
           "\nColumns: f_w, f_E, f_F, f_a, f_delta, f_sigma, w = w/(Y R0),\n"
           "sigma_max = sigma0/Y, lambda_theory, mu_tabor.\n"
           "\nexample: cgcm-analytic map --gammaL 50 --gammaW 200 --nu 0.2\n",
       join({kCgcmOptions, kCommonOptions}), runMap},
      {"fit", "Least-squares M-D lambda (and optional approach offset) for a CGCM load curve.",
       "options:\n"
       "  --curve FILE     load curve CSV with a header (columns read by name)\n"
       "  --gammaL G --gammaW G --nu V   as for `map` (required)\n"
       "  --fit-offset     also fit an offset: u = f_delta delta + offset\n"
       "  --offset X       the fixed offset, or the centre of its search (default 0)\n"
       "  --offset-bound D half-width of the offset search (default: half the u-span\n"
       "                   of the fitted points)\n"
       "  --u-min U --u-max U\n"
       "                   fit the points with U-min <= u <= U-max (default: u >= u at\n"
       "                   the minimum of P, i.e. the pull-off point and the contact side)\n"
       "  --lambda-min L --lambda-max L   search range (default 1e-3 and 1e3)\n"
       "  --u-column NAME --P-column NAME column names (default u and P)\n" +
           kCommonHelp +
           "\nThe model is P = f_F P_MD(a), u = f_delta delta_MD(a) + offset on the\n"
           "displacement-control branch; the residual is in P at the data's u.\n"
           "\nexample: cgcm-analytic fit --curve load_curve.csv --gammaL 50 --gammaW 200 --nu 0.2\n",
       join({kCgcmOptions, kCommonOptions,
             {{"curve", true, ""}, {"fit-offset", false, ""}, {"offset", true, ""},
              {"offset-bound", true, ""}, {"u-min", true, ""}, {"u-max", true, ""},
              {"lambda-min", true, ""}, {"lambda-max", true, ""}, {"u-column", true, ""},
              {"P-column", true, ""}}}),
       runFit},
      {"ljsphere",
       "Lennard-Jones sphere (Greenwood 1997, Feng 2000): retraction branch at Tabor mu.",
       "options:\n"
       "  --mu M           Tabor parameter (R w^2/(E*^2 z0^3))^(1/3), 1e-3 <= M <= 1e3\n"
       "                   (required)\n"
       "  --rings N        number of rings of the discretisation, 50 to 5000\n"
       "                   (default 200; the cost grows like N^3)\n"
       "  --delta-start D  starting approach delta/z0 in compression (default 0:\n"
       "                   automatic, the JKR approach at 1.2 times the zero-load radius)\n"
       "  --pulloff        write only mu, P_min, delta_at_min, contact_radius_at_min,\n"
       "                   peak_radius_at_min (the minimum of P along the branch)\n" +
           kCommonHelp +
           "\nThe 9-3 surface law sigma(h) = (8w/(3z0))[(z0/h)^9 - (z0/h)^3] between an\n"
           "elastic sphere and half-space, solved self-consistently with Boussinesq\n"
           "elasticity (Greenwood 1997), retracted under displacement control from\n"
           "compression to the end of the contact branch (fold or separation).\n"
           "Columns: delta_over_z0 = delta/z0 (approach), P_over_piwR = P/(pi w R)\n"
           "(compression positive), and two radii in the Johnson-Greenwood units of\n"
           "`curve`, a (4E*/(3 pi w R^2))^(1/3): contact_radius, the outermost radius\n"
           "where the traction changes sign (0 without a compressive zone; in the JKR\n"
           "limit inside JKR's a, whose pressure turns tensile before the edge), and\n"
           "peak_radius, the outermost radius of peak tension (h = 3^(1/6) z0), which\n"
           "tends to JKR's a. P_min is the minimum force along the branch: -3/2 as\n"
           "mu -> inf (JKR), -2 as mu -> 0 (Bradley). The run time grows like mu^2\n"
           "above mu = 3 (seconds at mu = 10). Run statistics go to stderr.\n"
           "\nexample: cgcm-analytic ljsphere --mu 3 --pulloff\n",
       join({kCommonOptions, {{"mu", true, ""}, {"rings", true, ""}, {"delta-start", true, ""},
                              {"pulloff", false, ""}}}),
       runLjSphere},
      {"cylinder",
       "Cylinder on a half-space in plane strain, per unit length: columns a, P, c.",
       "options:\n"
       "  --model M        hertz, jkr or md (required)\n"
       "  --lambda L       Maugis-Dugdale parameter of the cylinder,\n"
       "                   lambda = 2 sigma0 (R/(pi w E*^2))^(1/3); required for md and\n"
       "                   only for md; 1e-3 <= L <= 1e3\n"
       "  --a-min A        smallest half-width (default 1e-3)\n"
       "  --a-max A        largest half-width (default 3)\n"
       "  --points N       number of half-widths, evenly spaced (default 300)\n"
       "  --pulloff        write only the load-control pull-off point\n"
       "  --Estar E --w W --R R\n"
       "                   optional, all three or none: the plane-strain combined modulus,\n"
       "                   the work of adhesion and the radius; adds the columns a_phys,\n"
       "                   P_phys (per unit length) and c_phys\n" +
           kCommonHelp +
           "\nNormalised by a = a_bar (pi w R^2/E*)^(1/3), P = P_bar (pi^2 w^2 E* R)^(1/3):\n"
           "Hertz P_bar = pi a^2/4; JKR (Barquins 1988) P_bar = pi a^2/4 - sqrt(2a), pull-off\n"
           "-3/(16 pi)^(1/3) = -0.81289, i.e. P_c/L = -3 (pi E* w^2 R/16)^(1/3); Maugis-Dugdale\n"
           "(Baney & Hui 1997) P_bar = pi a^2/4 - lambda a sqrt(m^2 - 1) with m = c/a from the\n"
           "gap equation (doc/analytic-models.md). c is the outer half-width of the loaded\n"
           "zone (= a except for md). Plane strain has no approach, hence no displacement-\n"
           "control pull-off.\n"
           "\nexample: cgcm-analytic cylinder --model md --lambda 1 --pulloff\n",
       join({kCommonOptions, {{"model", true, ""}, {"lambda", true, ""}, {"a-min", true, ""},
                              {"a-max", true, ""}, {"points", true, ""}, {"pulloff", false, ""},
                              {"Estar", true, ""}, {"w", true, ""}, {"R", true, ""}}}),
       runCylinder},
      {"peel",
       "Kendall's steady peel force against the angle: columns theta_deg, F_over_bw,\n"
       "inextensible_F_over_bw, held_end_F_over_bw.",
       "options:\n"
       "  --epsilon X      w/(E_t h) >= 0 (required): work of adhesion over the strip's\n"
       "                   tension modulus times its thickness; E_t = E/(1 - nu^2) in plane\n"
       "                   strain (a wide strip), E for a narrow one\n"
       "  --theta-min D    smallest peel angle in degrees (default 0)\n"
       "  --theta-max D    largest peel angle in degrees (default 180)\n"
       "  --points N       number of angles, evenly spaced (default 181)\n"
       "  --theta D        a single angle instead of the range\n" +
           kCommonHelp +
           "\nKendall (1975): (F/b)^2/(2 E_t h) + (F/b)(1 - cos theta) - w = 0, written\n"
           "F/(b w) = 2/[(1 - cos theta) + sqrt((1 - cos theta)^2 + 2 epsilon)]; the\n"
           "inextensible limit is 1/(1 - cos theta) (inf at 0 degrees). held_end: the strip\n"
           "held at its far end on a bond that carries no shear (a Lennard-Jones bond to a\n"
           "flat substrate): its bonded part carries F cos theta, and the balance reads\n"
           "(F/b)^2 sin^2(theta)/(2 E_t h) + (F/b)(1 - cos theta) - w = 0 (inf at 0 degrees;\n"
           "doc/analytic-models.md).\n"
           "\nexample: cgcm-analytic peel --epsilon 1e-3 --theta 90\n",
       join({kCommonOptions, {{"epsilon", true, ""}, {"theta-min", true, ""}, {"theta-max", true, ""},
                              {"points", true, ""}, {"theta", true, ""}}}),
       runPeel},
      {"punch",
       "Flat-punch pull-off: Kendall's force against the strength limit over the punch\n"
       "size: columns a_over_acr, kendall_over_strength.",
       "options:\n"
       "  --geometry G     axisymmetric (radius a) or strip (half-width a, plane strain,\n"
       "                   per unit length) (required)\n"
       "  --a-min X        smallest size in multiples of the critical size (default 1e-2)\n"
       "  --a-max X        largest size in multiples of the critical size (default 1e2)\n"
       "  --points N       number of sizes, logarithmically spaced (default 41)\n"
       "  --Estar E --w W --sigma-max S\n"
       "                   optional, all three or none: the half-space's E/(1 - nu^2), the\n"
       "                   work of adhesion and the interface strength; adds the columns a,\n"
       "                   F_kendall and F_strength, and prints a_cr on stderr\n" +
           kCommonHelp +
           "\nAxisymmetric: F_kendall = sqrt(8 pi a^3 E* w) (Kendall 1971), F_strength =\n"
           "pi a^2 sigma_max, a_cr = 8 E* w/(pi sigma_max^2). Strip: F_kendall =\n"
           "sqrt(2 pi a E* w), F_strength = 2 a sigma_max, a_cr = pi E* w/(2 sigma_max^2).\n"
           "In both, F_kendall/F_strength = sqrt(a_cr/a) (Gao & Yao 2004).\n"
           "\nexample: cgcm-analytic punch --geometry axisymmetric --Estar 1 --w 1e-3 --sigma-max 0.02\n",
       join({kCommonOptions, {{"geometry", true, ""}, {"a-min", true, ""}, {"a-max", true, ""},
                              {"points", true, ""}, {"Estar", true, ""}, {"w", true, ""},
                              {"sigma-max", true, ""}}}),
       runPunch},
  };
}

std::string globalUsage(const std::vector<Command>& cmds) {
  std::ostringstream out;
  out << "usage: " << kProgram << " <command> [options]\n\n"
      << "Closed-form adhesive contact of a sphere on a half-space (Hertz, JKR, DMT,\n"
      << "Maugis-Dugdale) in the Johnson-Greenwood normalisation, their mapping to the\n"
      << "CGCM, and the Lennard-Jones sphere at a Tabor parameter mu (ljsphere); beyond\n"
      << "the sphere, the JKR and Maugis-Dugdale cylinders (cylinder), Kendall's peel\n"
      << "(peel) and the flat punch (punch). Each command writes CSV with a header to\n"
      << "stdout (or --output FILE).\n\n"
      << "commands:\n";
  for (const auto& c : cmds) {
    std::string first = c.summary.substr(0, c.summary.find('\n'));
    out << "  " << c.name << std::string(c.name.size() < 10 ? 10 - c.name.size() : 1, ' ')
        << first << "\n";
  }
  out << "\n`" << kProgram << " <command> --help` describes a command's options.\n";
  return out.str();
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<Command> cmds = commands();
  std::vector<std::string> rest(argv + 1, argv + argc);
  if (rest.empty()) {
    std::cerr << kProgram << ": missing command\n\n" << globalUsage(cmds);
    return 2;
  }
  if (rest[0] == "--help" || rest[0] == "-h" || rest[0] == "help") {
    std::cout << globalUsage(cmds);
    return 0;
  }
  const Command* cmd = nullptr;
  for (const auto& c : cmds) {
    if (c.name == rest[0]) cmd = &c;
  }
  if (!cmd) {
    std::string names;
    for (const auto& c : cmds) names += (names.empty() ? "" : ", ") + c.name;
    std::cerr << kProgram << ": unknown command '" << rest[0] << "' (allowed: " << names
              << ")\n\n"
              << globalUsage(cmds);
    return 2;
  }
  rest.erase(rest.begin());
  try {
    Args args(*cmd, rest);
    if (args.has("help")) {
      std::cout << usageOf(*cmd);
      return 0;
    }
    if (args.has("output")) {
      const std::string path = args.text("output");
      std::ofstream file(path);
      if (!file) throw UsageError("option --output: cannot open '" + path + "' for writing");
      cmd->run(args, file);
      file.flush();
      if (!file) {
        std::cerr << kProgram << " " << cmd->name << ": error writing '" << path << "'\n";
        return 1;
      }
    } else {
      cmd->run(args, std::cout);
      std::cout.flush();
    }
    return 0;
  } catch (const UsageError& e) {
    std::cerr << kProgram << " " << cmd->name << ": " << e.what() << "\n\n" << usageOf(*cmd);
    return 2;
  } catch (const cgcm::InputError& e) {
    std::cerr << kProgram << " " << cmd->name << ": " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << kProgram << " " << cmd->name << ": error: " << e.what() << "\n";
    return 1;
  }
}
