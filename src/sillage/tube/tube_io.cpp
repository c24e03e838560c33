#include "sillage/tube/tube_io.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <istream>
#include <ostream>
#include <streambuf>
#include <string>
#include <utility>

#include "sillage/error.h"
#include "sillage/read_file.h"

namespace sillage {

namespace {

constexpr char kMagic[8] = {'S', 'L', 'G', 'T', 'U', 'B', 'E', '\0'};
constexpr std::uint32_t kKindTube = 1, kKindTubeVector = 2;

// ---- writing: explicit little-endian bytes -------------------------------

void put_u64(std::ostream& os, std::uint64_t v) {
  char b[8];
  for (int i = 0; i < 8; ++i) b[i] = static_cast<char>((v >> (8 * i)) & 0xff);
  os.write(b, 8);
}
void put_u32(std::ostream& os, std::uint32_t v) {
  char b[4];
  for (int i = 0; i < 4; ++i) b[i] = static_cast<char>((v >> (8 * i)) & 0xff);
  os.write(b, 4);
}
void put_f64(std::ostream& os, double x) { put_u64(os, std::bit_cast<std::uint64_t>(x)); }
void put_interval(std::ostream& os, const Interval& y) {
  if (y.is_empty()) {
    put_f64(os, rounding::kInf);
    put_f64(os, -rounding::kInf);
  } else {
    put_f64(os, y.lb());
    put_f64(os, y.ub());
  }
}

void write_all(std::ostream& os, std::uint32_t kind, const TDomain& td, const std::vector<const Tube*>& xs) {
  os.write(kMagic, 8);
  put_u32(os, kTubeFileVersion);
  put_u32(os, kind);
  put_u64(os, td.nb_slices() + 1);
  for (double t : td.times()) put_f64(os, t);
  put_u64(os, xs.size());
  for (const Tube* x : xs) {
    for (const auto& y : x->slices()) put_interval(os, y);
    for (const auto& y : x->gates()) put_interval(os, y);
  }
  if (!os) throw Error("save(tube): write error");
}

// ---- reading: every field checked -----------------------------------------

// Every message starts with `where`: "load tube: " for a stream, "load tube:
// 'path': " for a file, so that a bad file is named.
class Reader {
 public:
  Reader(std::istream& is, std::string where) : is_(is), where_(std::move(where)) {}
  const std::string& where() const { return where_; }

  void bytes(char* out, std::size_t n, const char* what) {
    is_.read(out, static_cast<std::streamsize>(n));
    if (static_cast<std::size_t>(is_.gcount()) != n) {
      throw Error(where_ + "file truncated at byte " + std::to_string(offset_ + is_.gcount()) + " while reading " +
                  what);
    }
    offset_ += n;
  }
  std::uint64_t u64(const char* what) {
    unsigned char b[8];
    bytes(reinterpret_cast<char*>(b), 8, what);
    std::uint64_t v = 0;
    for (int i = 7; i >= 0; --i) v = (v << 8) | b[i];
    return v;
  }
  std::uint32_t u32(const char* what) {
    unsigned char b[4];
    bytes(reinterpret_cast<char*>(b), 4, what);
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = (v << 8) | b[i];
    return v;
  }
  double f64(const char* what) { return std::bit_cast<double>(u64(what)); }
  Interval interval(const char* what) {
    const std::size_t at = offset_;
    const double lb = f64(what), ub = f64(what);
    if (lb == rounding::kInf && ub == -rounding::kInf) return Interval::empty();
    if (std::isnan(lb) || std::isnan(ub) || lb > ub || lb == rounding::kInf || ub == -rounding::kInf) {
      throw Error(where_ + "invalid bounds (" + number_text(lb) + ", " + number_text(ub) + ") for " + what + " at byte " +
                  std::to_string(at));
    }
    return Interval(lb, ub);
  }
  std::size_t offset() const { return offset_; }

 private:
  std::istream& is_;
  std::string where_;
  std::size_t offset_ = 0;
};

// The time points: finite and increasing, or equal to those of the given
// TDomain. An error names the first bad one, its byte and its value.
void check_times(const Reader& r, const std::vector<double>& times, std::size_t at, const TDomain* td) {
  const auto point = [&](std::size_t k) {
    return r.where() + "time point " + std::to_string(k) + " (byte " + std::to_string(at + 8 * k) + ") is " +
           number_text(times[k]);
  };
  if (td && td->nb_slices() + 1 != times.size()) {
    throw DimensionError(r.where() + "the file has " + std::to_string(times.size()) + " time points, the given TDomain " +
                         std::to_string(td->nb_slices() + 1));
  }
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (td) {
      if (times[k] != td->t(k)) throw DimensionError(point(k) + ", the given TDomain's is " + number_text(td->t(k)));
    } else if (!std::isfinite(times[k])) {
      throw Error(point(k) + ", not a finite time");
    } else if (k > 0 && !(times[k - 1] < times[k])) {
      throw Error(point(k) + ", not after time point " + std::to_string(k - 1) + " = " + number_text(times[k - 1]));
    }
  }
}

struct Loaded {
  std::shared_ptr<TDomain> td;
  std::vector<Tube> tubes;
  std::size_t end = 0;  // bytes read
};

Loaded read_all(std::istream& is, std::uint32_t expected_kind, std::shared_ptr<TDomain> td,
                const std::string& path = "") {
  Reader r(is, path.empty() ? "load tube: " : "load tube: '" + path + "': ");
  char magic[8];
  r.bytes(magic, 8, "the magic number");
  if (std::memcmp(magic, kMagic, 8) != 0) throw Error(r.where() + "not a sillage tube file (bad magic number at byte 0)");
  const std::uint32_t version = r.u32("the format version");
  if (version != kTubeFileVersion) {
    throw Error(r.where() + "unsupported format version " + std::to_string(version) + " (this library reads version " +
                std::to_string(kTubeFileVersion) + ")");
  }
  const std::uint32_t kind = r.u32("the kind");
  if (kind != expected_kind) {
    throw Error(r.where() + "the file holds a " + std::string(kind == kKindTube ? "Tube" : kind == kKindTubeVector ? "TubeVector" : "unknown object") +
                ", a " + (expected_kind == kKindTube ? "Tube" : "TubeVector") + " was expected");
  }
  const std::uint64_t nt = r.u64("the number of time points");
  if (nt < 2 || nt > (std::uint64_t{1} << 31)) {
    throw Error(r.where() + "invalid number of time points " + std::to_string(nt) + " at byte " +
                std::to_string(r.offset() - 8));
  }
  const std::size_t times_at = r.offset();
  std::vector<double> times;
  for (std::uint64_t k = 0; k < nt; ++k) times.push_back(r.f64("the time points"));
  check_times(r, times, times_at, td.get());
  if (!td) td = TDomain::create(std::move(times));
  const std::uint64_t n = r.u64("the number of components");
  if (n == 0 || (kind == kKindTube && n != 1) || n > (std::uint64_t{1} << 20)) {
    throw Error(r.where() + "invalid number of components " + std::to_string(n));
  }
  Loaded out{td, {}};
  const std::size_t ns = td->nb_slices();
  for (std::uint64_t i = 0; i < n; ++i) {
    std::vector<Interval> slices, gates;
    for (std::size_t k = 0; k < ns; ++k) slices.push_back(r.interval("a slice"));
    for (std::size_t k = 0; k <= ns; ++k) gates.push_back(r.interval("a gate"));
    out.tubes.emplace_back(td, slices, gates);
  }
  out.end = r.offset();
  return out;
}

std::ofstream open_out(const std::string& path) {
  std::ofstream os(path, std::ios::binary);
  if (!os) throw Error("save(tube, path): cannot open '" + path + "' for writing");
  return os;
}
// The bytes of a file read whole, as a stream for the reader (not copied).
struct BytesBuf : std::streambuf {
  explicit BytesBuf(std::string& s) { setg(s.data(), s.data(), s.data() + s.size()); }
};

// A file holds one object: bytes after it are an error (a stream may go on).
Loaded read_file(const std::string& path, std::uint32_t kind, std::shared_ptr<TDomain> td) {
  std::string bytes = read_file_bytes(path, "load tube", "a tube file");
  BytesBuf buf(bytes);
  std::istream is(&buf);
  Loaded out = read_all(is, kind, std::move(td), path);
  if (out.end != bytes.size()) {
    throw Error("load tube: '" + path + "' has trailing bytes after the " +
                (kind == kKindTube ? "Tube" : "TubeVector") + ", from byte " + std::to_string(out.end));
  }
  return out;
}

}  // namespace

void save(const Tube& x, std::ostream& os) { write_all(os, kKindTube, *x.tdomain(), {&x}); }

void save(const TubeVector& x, std::ostream& os) {
  std::vector<const Tube*> xs;
  for (std::size_t i = 0; i < x.size(); ++i) xs.push_back(&x[i]);
  write_all(os, kKindTubeVector, *x.tdomain(), xs);
}

void save(const Tube& x, const std::string& path) {
  auto os = open_out(path);
  save(x, os);
}
void save(const TubeVector& x, const std::string& path) {
  auto os = open_out(path);
  save(x, os);
}

Tube load_tube(std::istream& is, std::shared_ptr<TDomain> td) {
  return std::move(read_all(is, kKindTube, std::move(td)).tubes.front());
}

TubeVector load_tube_vector(std::istream& is, std::shared_ptr<TDomain> td) {
  return TubeVector(read_all(is, kKindTubeVector, std::move(td)).tubes);
}

Tube load_tube(const std::string& path, std::shared_ptr<TDomain> td) {
  return std::move(read_file(path, kKindTube, std::move(td)).tubes.front());
}
TubeVector load_tube_vector(const std::string& path, std::shared_ptr<TDomain> td) {
  return TubeVector(read_file(path, kKindTubeVector, std::move(td)).tubes);
}

}  // namespace sillage
