#include "cgcm/solver/Checkpoint.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <boost/crc.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>

#include "cgcm/solver/RootStream.hpp"

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
// The fields of format 2 after its magic up to the vectors: the stepper, the continuity check's u, the
// Exodus steps, the curve.
std::string headerFields(const Checkpoint& c) {
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
  return out.str();
}

// The header fields back from `in`; false if they do not fit together (more rows than `size` bytes).
bool parseHeader(std::istream& in, std::uint64_t size, Checkpoint& c) {
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
  return bool(in);
}

// Writes through a temporary file, the CRC-32 of every byte kept as it goes; commit() appends the CRC
// and renames the file into place.
class ChecksummedFile {
 public:
  explicit ChecksummedFile(const std::string& path)
      : path_(path), temporary_(path + ".tmp"), out_(temporary_, std::ios::binary | std::ios::trunc) {}
  void write(const void* data, std::size_t size) {
    out_.write(static_cast<const char*>(data), std::streamsize(size));
    crc_.process_bytes(data, size);
  }
  template <class T>
  void write(const T& v) {
    write(&v, sizeof v);
  }
  bool commit() {
    const Checksum crc = Checksum(crc_.checksum());
    put(out_, crc);
    out_.flush();
    out_.close();
    if (!out_) return false;
    std::error_code ec;
    std::filesystem::rename(temporary_, path_, ec);
    return !ec;
  }

 private:
  std::string path_, temporary_;
  std::ofstream out_;
  boost::crc_32_type crc_;
};

void writeStart(ChecksummedFile& file, const Checkpoint& c) {
  file.write(kMagicStem, sizeof kMagicStem);
  file.write(kVersion);
  const std::string header = headerFields(c);
  file.write(header.data(), header.size());
}

// Values of the file's vectors as they are read: vector 0 (u) or 1 (previous), entries [first, first + count).
using VectorSink = std::function<void(int vector, std::uint64_t first, const Real* values, std::size_t count)>;

// The checkpoint file at `path`, checked whole before any field is read: its format, its size and its
// checksum, a window of bytes at a time. Throws MissingCheckpoint or InputError (as readCheckpoint).
// Returns the file's size.
std::uint64_t checkedFile(const std::string& path, std::size_t windowBytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MissingCheckpoint("no checkpoint (" + path + ")");
  in.seekg(0, std::ios::end);
  const std::uint64_t size = std::uint64_t(in.tellg());
  in.seekg(0);
  if (in.bad() || !in) throw InputError("cannot read " + path);
  constexpr std::size_t header = sizeof kMagicStem + 1;
  char start[header] = {};
  in.read(start, std::streamsize(std::min<std::uint64_t>(size, header)));
  const bool cgcm = size >= header && std::memcmp(start, kMagicStem, sizeof kMagicStem) == 0;
  const char version = cgcm ? start[sizeof kMagicStem] : 0;
  auto lastBytes = [&](char* out, std::size_t n) {
    in.clear();
    in.seekg(std::streamoff(size - n));
    in.read(out, std::streamsize(n));
  };
  // format 1: no checksum, the end mark last
  if (version == '1' && size >= header + sizeof kEnd) {
    char end[sizeof kEnd];
    lastBytes(end, sizeof end);
    if (std::memcmp(end, kEnd, sizeof kEnd) == 0)
      throw InputError(path + " is a checkpoint of format 1, written by an older cgcm; this cgcm reads format " +
                       kVersion + ": run the deck again from the start");
  }
  if (size < header + sizeof(Checksum))
    throw InputError(path + " is damaged or not a cgcm checkpoint (" + std::to_string(size) +
                     " bytes: too short for one)");
  Checksum stored = 0;
  lastBytes(reinterpret_cast<char*>(&stored), sizeof stored);
  const std::uint64_t body = size - sizeof(Checksum);
  boost::crc_32_type crc;
  std::vector<char> window(std::max<std::size_t>(1, windowBytes));
  in.clear();
  in.seekg(0);
  for (std::uint64_t done = 0; done < body;) {
    const std::size_t n = std::size_t(std::min<std::uint64_t>(window.size(), body - done));
    in.read(window.data(), std::streamsize(n));
    if (!in) throw InputError("cannot read " + path);
    crc.process_bytes(window.data(), n);
    done += n;
  }
  if (Checksum(crc.checksum()) != stored)
    throw InputError(path + " is damaged: its checksum (CRC-32) does not match its contents (the file was cut "
                     "or changed after cgcm wrote it, or it is not a cgcm checkpoint)");
  if (!cgcm) throw InputError(path + " is not a cgcm checkpoint");
  // a later format that keeps the checksum at the end
  if (version != kVersion)
    throw InputError(path + " is a checkpoint of format " + version + ", written by a newer cgcm; this cgcm reads "
                     "format " + kVersion);
  return size;
}

// Reads a checked file's fields: the header into `c`, the vectors' lengths into c.unknowns (u) and
// `previousLength`, their values to `sink` a window at a time (skipped without a sink). Throws InputError
// if the fields do not fit together.
void readFields(const std::string& path, std::uint64_t size, std::size_t windowBytes, Checkpoint& c,
                std::uint64_t& previousLength, const VectorSink& sink) {
  std::ifstream in(path, std::ios::binary);
  constexpr std::size_t header = sizeof kMagicStem + 1;
  const std::uint64_t body = size - sizeof(Checksum);
  in.seekg(std::streamoff(header));
  const std::string refused = path + " is not a cgcm checkpoint of format " + kVersion +
                              " (its fields do not fit together)";
  if (!parseHeader(in, body, c)) throw InputError(refused);
  std::vector<Real> window(std::max<std::size_t>(1, windowBytes / sizeof(Real)));
  for (int v = 0; v < 2; ++v) {
    std::uint64_t n = 0;
    get(in, n);
    const std::uint64_t at = std::uint64_t(in.tellg());
    if (!in || n > (body - at) / sizeof(Real)) throw InputError(refused);
    (v == 0 ? c.unknowns : previousLength) = n;
    if (!sink) {
      in.seekg(std::streamoff(at + n * sizeof(Real)));
      continue;
    }
    for (std::uint64_t first = 0; first < n;) {
      const std::size_t count = std::size_t(std::min<std::uint64_t>(window.size(), n - first));
      in.read(reinterpret_cast<char*>(window.data()), std::streamsize(count * sizeof(Real)));
      if (!in) throw InputError(refused);
      sink(v, first, window.data(), count);
      first += count;
    }
  }
  char end[sizeof kEnd];
  in.read(end, sizeof end);
  if (!in || std::memcmp(end, kEnd, sizeof kEnd) != 0 || std::uint64_t(in.tellg()) != body) throw InputError(refused);
}

}  // namespace

std::string checkpointPath(const std::string& dir) { return dir + "/checkpoint.bin"; }

bool writeCheckpoint(const std::string& dir, const Checkpoint& c) {
  ChecksummedFile file(checkpointPath(dir));
  writeStart(file, c);
  for (const std::vector<Real>* v : {&c.u, &c.previous}) {
    file.write(std::uint64_t(v->size()));
    file.write(v->data(), v->size() * sizeof(Real));
  }
  file.write(kEnd, sizeof kEnd);
  return file.commit();
}

Checkpoint readCheckpoint(const std::string& dir) {
  const std::string path = checkpointPath(dir);
  const std::uint64_t size = checkedFile(path, kRootStreamWindowBytes);
  Checkpoint c;
  std::uint64_t previous = 0;
  readFields(path, size, kRootStreamWindowBytes, c, previous,
             [&](int v, std::uint64_t, const Real* values, std::size_t count) {
               std::vector<Real>& to = v == 0 ? c.u : c.previous;
               to.insert(to.end(), values, values + count);
             });
  return c;
}

bool writeCheckpoint(const assembly::Comm& comm, const std::string& dir, const Checkpoint& c, const assembly::Vector& u,
                     const assembly::Vector* previous, std::size_t windowBytes) {
  const bool root = comm.getRank() == 0;
  std::unique_ptr<ChecksummedFile> file;
  if (root) {
    file = std::make_unique<ChecksummedFile>(checkpointPath(dir));
    writeStart(*file, c);
  }
  for (const assembly::Vector* v : {&u, previous}) {
    if (root) file->write(std::uint64_t(v ? v->getGlobalLength() : 0));
    if (!v) continue;
    // this rank's entries by global dof, ascending
    const auto& map = *v->getMap();
    std::vector<std::pair<GlobalIndex, LocalIndex>> order;
    for (std::size_t k = 0; k < map.getNodeNumElements(); ++k)
      order.emplace_back(map.getGlobalElement(LocalIndex(k)), LocalIndex(k));
    std::sort(order.begin(), order.end());
    std::vector<GlobalIndex> ids;
    std::vector<Real> values;
    {
      const auto h = v->getLocalViewHost(Tpetra::Access::ReadOnly);
      for (const auto& [id, k] : order) ids.push_back(id), values.push_back(h(std::size_t(k), 0));
    }
    std::uint64_t next = 0;  // the entries written: the windows follow each other without a gap
    streamToRoot<Real>(
        comm, ids, values, 1,
        [&](const std::vector<GlobalIndex>& at, const std::vector<Real>& w) {
          if (at.front() != GlobalIndex(next) || at.back() != GlobalIndex(next + at.size() - 1))
            throw std::logic_error("writeCheckpoint: dof " + std::to_string(next) + " sent by no rank");
          file->write(w.data(), w.size() * sizeof(Real));
          next += at.size();
        },
        windowBytes);
  }
  int written = 0;
  if (root) {
    file->write(kEnd, sizeof kEnd);
    written = file->commit() ? 1 : 0;
  }
  Teuchos::broadcast(comm, 0, Teuchos::outArg(written));
  return written != 0;
}

Checkpoint readCheckpointHeader(const std::string& dir, std::size_t windowBytes) {
  const std::string path = checkpointPath(dir);
  const std::uint64_t size = checkedFile(path, windowBytes);
  Checkpoint c;
  std::uint64_t previous = 0;
  readFields(path, size, windowBytes, c, previous, nullptr);
  return c;
}

void readCheckpointVectors(const std::string& dir, assembly::Vector& u, assembly::Vector* previous,
                           std::size_t windowBytes) {
  const std::string path = checkpointPath(dir);
  const std::uint64_t size = checkedFile(path, windowBytes);
  // per vector, this rank's entries (global dof, local index) ascending, and where the windows have got to
  std::vector<std::pair<GlobalIndex, LocalIndex>> order[2];
  std::size_t cursor[2] = {0, 0};
  assembly::Vector* to[2] = {&u, previous};
  for (int v = 0; v < 2; ++v) {
    if (!to[v]) continue;
    const auto& map = *to[v]->getMap();
    for (std::size_t k = 0; k < map.getNodeNumElements(); ++k)
      order[v].emplace_back(map.getGlobalElement(LocalIndex(k)), LocalIndex(k));
    std::sort(order[v].begin(), order[v].end());
  }
  auto lengthCheck = [&](int v, std::uint64_t n) {
    const std::uint64_t want = to[v] ? to[v]->getGlobalLength() : 0;
    if (to[v] && n != want)
      throw InputError("restart: the checkpoint holds " + std::to_string(n) + " unknowns" +
                       (v == 0 ? "" : " in its previous state") + ", the problem " + std::to_string(want));
  };
  Checkpoint c;
  std::uint64_t previousLength = 0;
  {
    // the lengths first, before any value lands in a vector
    readFields(path, size, windowBytes, c, previousLength, nullptr);
    lengthCheck(0, c.unknowns);
    if (previous) lengthCheck(1, previousLength);
  }
  auto h0 = u.getLocalViewHost(Tpetra::Access::OverwriteAll);
  decltype(h0) h1;
  if (previous) h1 = previous->getLocalViewHost(Tpetra::Access::OverwriteAll);
  readFields(path, size, windowBytes, c, previousLength,
             [&](int v, std::uint64_t first, const Real* values, std::size_t count) {
               if (!to[v]) return;
               auto& h = v == 0 ? h0 : h1;
               auto& at = cursor[v];
               const auto end = GlobalIndex(first + count);
               for (; at < order[v].size() && order[v][at].first < end; ++at)
                 h(std::size_t(order[v][at].second), 0) = values[std::size_t(order[v][at].first - GlobalIndex(first))];
             });
}

}  // namespace cgcm::solver
