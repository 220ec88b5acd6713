#include "cgcm/solver/Checkpoint.hpp"

#include <boost/crc.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace cgcm::solver {

namespace {

// Format 2: the fields below, then the CRC-32 (Boost's crc_32_type, as in
// zip and PNG) of every byte before it, so any byte changed after the write
// (header, curve, vectors) or a cut file is refused. Format 1 ("cgcmckp1")
// had no checksum.
constexpr char kMagicStem[7] = {'c', 'g', 'c', 'm', 'c', 'k', 'p'};
constexpr char kVersion = '2';
constexpr char kEnd[4] = {'e', 'n', 'd', '.'};
using Checksum = std::uint32_t;

Checksum crc32(const char* data, std::size_t size) {
  boost::crc_32_type crc;
  crc.process_bytes(data, size);
  return Checksum(crc.checksum());
}

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
// false if the count is impossible or the data run out
bool getVector(std::istream& in, std::vector<Real>& v, std::uint64_t limit) {
  std::uint64_t n = 0;
  get(in, n);
  if (!in || n > limit) return false;
  v.resize(n);
  in.read(reinterpret_cast<char*>(v.data()), std::streamsize(n * sizeof(Real)));
  return bool(in);
}

// The fields of format 2 after its magic, up to and with the end mark.
std::string fields(const Checkpoint& c) {
  std::ostringstream out(std::ios::binary);
  const auto& s = c.stepper;
  put(out, std::uint64_t(s.segment));
  put(out, s.displacement);
  put(out, s.increment);
  put(out, std::int32_t(s.step));
  put(out, std::uint8_t(s.havePrevious));
  put(out, s.previousDisplacement);
  put(out, c.lastDisplacement);
  put(out, std::int32_t(c.exodusSteps));
  put(out, std::uint64_t(c.curve.size()));
  for (const LoadPoint& p : c.curve) {
    put(out, std::int32_t(p.step));
    for (Real v : {p.u, p.P, p.parameter, p.gap, p.contactRadius, p.Plower, p.residual}) put(out, v);
    put(out, std::int32_t(p.newtonIterations));
    put(out, std::int32_t(p.cutbacks));
    put(out, std::uint8_t(p.stable | (p.fold << 1) | (p.jump << 2) | (p.branchPoint << 3)));
  }
  putVector(out, c.u);
  putVector(out, c.previous);
  out.write(kEnd, sizeof kEnd);
  return out.str();
}

// The fields back from `in` (the bytes between the magic and the checksum);
// false if they do not fit together.
bool parseFields(std::istream& in, std::uint64_t size, Checkpoint& c) {
  std::uint64_t segment = 0, rows = 0;
  std::int32_t step = 0, exodusSteps = 0;
  std::uint8_t havePrevious = 0;
  get(in, segment);
  get(in, c.stepper.displacement);
  get(in, c.stepper.increment);
  get(in, step);
  get(in, havePrevious);
  get(in, c.stepper.previousDisplacement);
  get(in, c.lastDisplacement);
  get(in, exodusSteps);
  get(in, rows);
  if (!in || rows > size) return false;
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
    p.branchPoint = (flags >> 3) & 1;
  }
  if (!in) return false;
  if (!getVector(in, c.u, size / sizeof(Real)) || !getVector(in, c.previous, size / sizeof(Real))) return false;
  char end[sizeof kEnd];
  in.read(end, sizeof end);
  return in && std::memcmp(end, kEnd, sizeof kEnd) == 0 && in.peek() == std::char_traits<char>::eof();
}

}  // namespace

std::string checkpointPath(const std::string& dir) { return dir + "/checkpoint.bin"; }

bool writeCheckpoint(const std::string& dir, const Checkpoint& c) {
  const std::string path = checkpointPath(dir), temporary = path + ".tmp";
  std::string bytes(kMagicStem, sizeof kMagicStem);
  bytes += kVersion;
  bytes += fields(c);
  const Checksum crc = crc32(bytes.data(), bytes.size());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    put(out, crc);
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
  if (!in) throw MissingCheckpoint("no checkpoint (" + path + ")");
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw InputError("cannot read " + path);
  const std::string& refused = path;
  constexpr std::size_t header = sizeof kMagicStem + 1;
  const bool cgcm = bytes.size() >= header && std::memcmp(bytes.data(), kMagicStem, sizeof kMagicStem) == 0;
  const char version = cgcm ? bytes[sizeof kMagicStem] : 0;
  // format 1: no checksum, the end mark last
  if (version == '1' && bytes.size() >= header + sizeof kEnd &&
      std::memcmp(bytes.data() + bytes.size() - sizeof kEnd, kEnd, sizeof kEnd) == 0)
    throw InputError(refused + " is a checkpoint of format 1, written by an older cgcm; this cgcm reads format " +
                     kVersion + ": run the deck again from the start");
  if (bytes.size() < header + sizeof(Checksum))
    throw InputError(refused + " is damaged or not a cgcm checkpoint (" + std::to_string(bytes.size()) +
                     " bytes: too short for one)");
  Checksum stored = 0;
  std::memcpy(&stored, bytes.data() + bytes.size() - sizeof stored, sizeof stored);
  const std::size_t body = bytes.size() - sizeof(Checksum);
  if (crc32(bytes.data(), body) != stored)
    throw InputError(refused + " is damaged: its checksum (CRC-32) does not match its contents (the file was cut "
                     "or changed after cgcm wrote it, or it is not a cgcm checkpoint)");
  if (!cgcm) throw InputError(refused + " is not a cgcm checkpoint");
  // a later format that keeps the checksum at the end
  if (version != kVersion)
    throw InputError(refused + " is a checkpoint of format " + version + ", written by a newer cgcm; this cgcm reads "
                     "format " + kVersion);
  Checkpoint c;
  std::istringstream fieldsIn(bytes.substr(header, body - header), std::ios::binary);
  if (!parseFields(fieldsIn, body, c))
    throw InputError(refused + " is not a cgcm checkpoint of format " + kVersion + " (its fields do not fit together)");
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
  // every rank reads the same checkpoint, so every rank refuses it here, before the collective export
  const std::size_t unknowns = all_->getMap()->getGlobalNumElements();
  if (values.size() != unknowns)
    throw InputError("restart: the checkpoint holds " + std::to_string(values.size()) + " unknowns, the problem " +
                     std::to_string(unknowns));
  {
    const auto v = all_->getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t k = 0; k < v.extent(0); ++k) v(k, 0) = values[k];
  }
  x.doExport(*all_, *import_, Tpetra::INSERT);
}

}  // namespace cgcm::solver
