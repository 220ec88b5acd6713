#include "cgcm/app/Checkpoint.hpp"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "cgcm/core/Error.hpp"

namespace cgcm::app {

namespace {

constexpr char kMagic[8] = {'c', 'g', 'c', 'm', 'c', 'k', 'p', '1'};
constexpr char kEnd[4] = {'e', 'n', 'd', '.'};

template <class T>
void put(std::ostream& out, const T& v) {
  out.write(reinterpret_cast<const char*>(&v), sizeof v);
}
template <class T>
void get(std::istream& in, T& v) {
  in.read(reinterpret_cast<char*>(&v), sizeof v);
}
void putVector(std::ostream& out, const std::vector<Real>& v) {
  put(out, std::uint64_t(v.size()));
  out.write(reinterpret_cast<const char*>(v.data()), std::streamsize(v.size() * sizeof(Real)));
}
void getVector(std::istream& in, std::vector<Real>& v, std::uint64_t limit) {
  std::uint64_t n = 0;
  get(in, n);
  if (!in || n > limit) throw InputError("");
  v.resize(n);
  in.read(reinterpret_cast<char*>(v.data()), std::streamsize(n * sizeof(Real)));
}

}  // namespace

std::string checkpointPath(const std::string& dir) { return dir + "/checkpoint.bin"; }

bool writeCheckpoint(const std::string& dir, const Checkpoint& c) {
  const std::string path = checkpointPath(dir), temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(kMagic, sizeof kMagic);
    const auto& s = c.stepper;
    put(out, std::uint64_t(s.segment));
    put(out, s.load);
    put(out, s.increment);
    put(out, std::int32_t(s.step));
    put(out, std::uint8_t(s.havePrevious));
    put(out, s.previousLoad);
    put(out, c.lastLoad);
    put(out, std::int32_t(c.exodusSteps));
    put(out, std::uint64_t(c.curve.size()));
    for (const LoadPoint& p : c.curve) {
      put(out, std::int32_t(p.step));
      for (Real v : {p.u, p.P, p.parameter, p.gap, p.contactRadius, p.Plower, p.residual}) put(out, v);
      put(out, std::int32_t(p.newtonIterations));
      put(out, std::int32_t(p.cutbacks));
      put(out, std::uint8_t(p.stable | (p.fold << 1) | (p.jump << 2)));
    }
    putVector(out, c.u);
    putVector(out, c.previous);
    out.write(kEnd, sizeof kEnd);
    out.flush();
    if (!out) return false;
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  return !ec;
}

Checkpoint readCheckpoint(const std::string& dir) {
  const std::string path = checkpointPath(dir);
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError("--restart " + dir + ": no checkpoint (" + path +
                     "): the run recorded no state, or Output/Checkpoint was false");
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw InputError("--restart " + dir + ": cannot read " + path + " (" + ec.message() + ")");
  Checkpoint c;
  try {
    char magic[sizeof kMagic];
    in.read(magic, sizeof magic);
    if (!in || std::memcmp(magic, kMagic, sizeof kMagic) != 0) throw InputError("");
    std::uint64_t segment = 0, rows = 0;
    std::int32_t step = 0, exodusSteps = 0;
    std::uint8_t havePrevious = 0;
    get(in, segment);
    get(in, c.stepper.load);
    get(in, c.stepper.increment);
    get(in, step);
    get(in, havePrevious);
    get(in, c.stepper.previousLoad);
    get(in, c.lastLoad);
    get(in, exodusSteps);
    get(in, rows);
    if (!in || rows > size) throw InputError("");
    c.stepper.segment = std::size_t(segment);
    c.stepper.step = step;
    c.stepper.havePrevious = havePrevious != 0;
    c.exodusSteps = exodusSteps;
    c.curve.resize(rows);
    for (LoadPoint& p : c.curve) {
      std::int32_t s = 0, iterations = 0, cutbacks = 0;
      std::uint8_t flags = 0;
      get(in, s);
      for (Real* v : {&p.u, &p.P, &p.parameter, &p.gap, &p.contactRadius, &p.Plower, &p.residual}) get(in, *v);
      get(in, iterations);
      get(in, cutbacks);
      get(in, flags);
      p.step = s;
      p.newtonIterations = iterations;
      p.cutbacks = cutbacks;
      p.stable = flags & 1;
      p.fold = (flags >> 1) & 1;
      p.jump = (flags >> 2) & 1;
    }
    getVector(in, c.u, size / sizeof(Real));
    getVector(in, c.previous, size / sizeof(Real));
    char end[sizeof kEnd];
    in.read(end, sizeof end);
    if (!in || std::memcmp(end, kEnd, sizeof kEnd) != 0) throw InputError("");
  } catch (const InputError&) {
    throw InputError("--restart " + dir + ": " + path + " is truncated or not a cgcm checkpoint");
  }
  return c;
}

RootGather::RootGather(const Teuchos::RCP<const assembly::Map>& owned) {
  const bool root = owned->getComm()->getRank() == 0;
  std::vector<GlobalIndex> gids;  // dof = node * dim + i: the gids are 0 .. n - 1
  if (root)
    for (GlobalIndex g = 0; g < GlobalIndex(owned->getGlobalNumElements()); ++g) gids.push_back(g);
  const auto rootMap =
      Teuchos::rcp(new assembly::Map(owned->getGlobalNumElements(), gids.data(), gids.size(), 0, owned->getComm()));
  import_ = Teuchos::rcp(new assembly::Import(owned, rootMap));
  all_ = Teuchos::rcp(new assembly::Vector(rootMap));
}

std::vector<Real> RootGather::gather(const assembly::Vector& x) {
  all_->doImport(x, *import_, Tpetra::INSERT);
  const auto v = all_->getLocalViewHost(Tpetra::Access::ReadOnly);
  std::vector<Real> out(v.extent(0));
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = v(k, 0);
  return out;
}

void RootGather::scatter(const std::vector<Real>& values, assembly::Vector& x) {
  {
    const auto v = all_->getLocalViewHost(Tpetra::Access::OverwriteAll);
    if (v.extent(0) > 0 && values.size() != v.extent(0))
      throw InputError("restart: the checkpoint holds " + std::to_string(values.size()) + " unknowns, the problem " +
                       std::to_string(v.extent(0)));
    for (std::size_t k = 0; k < v.extent(0); ++k) v(k, 0) = values[k];
  }
  x.doExport(*all_, *import_, Tpetra::INSERT);
}

}  // namespace cgcm::app
