#include "data/GribFile.hpp"

#include <eccodes.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <system_error>
#include <utility>
#include <vector>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "data/GridLayout.hpp"

namespace og::data::detail {
namespace fs = std::filesystem;

namespace {

/// Limits checked before anything is allocated from header values.
constexpr std::size_t kMaxMessages = 100000;
constexpr std::uint64_t kMaxMessageBytes = std::uint64_t{1} << 31;  // ecCodes' own limit
constexpr std::size_t kScanChunk = std::size_t{1} << 20;

/// ecCodes is called from one thread at a time.
std::mutex& gribMutex() {
  static std::mutex mutex;
  return mutex;
}

/// ecCodes' internal consistency failures: thrown from its assertion hook instead of abort().
struct GribAssertion {
  std::string message;
};

void configureEccodes() {
  static std::once_flag once;
  std::call_once(once, [] {
    // ecCodes prints its errors to stderr; ours are one line, so send its text to the debug log.
    codes_context_set_logging_proc(
        codes_context_get_default(),
        [](const codes_context*, int, const char* message) {
          log::debug(std::string("ecCodes: ") + (message != nullptr ? message : ""));
        });
    codes_set_codes_assertion_failed_proc(
        [](const char* message) { throw GribAssertion{message != nullptr ? message : "?"}; });
  });
}

/// Bytes of a file or an in-memory image, read at offsets.
class ByteSource {
 public:
  ByteSource(const fs::path& file, std::string label) : label_(std::move(label)) {
    std::error_code ec;
    if (!fs::exists(file, ec)) throw InputError(label_ + ": no such file");
    if (!fs::is_regular_file(file, ec)) throw InputError(label_ + ": not a regular file");
    size_ = fs::file_size(file, ec);
    if (ec) throw InputError(label_ + ": cannot determine the file size: " + ec.message());
    stream_.open(file, std::ios::binary);
    if (!stream_) throw InputError(label_ + ": cannot open for reading");
  }
  ByteSource(std::string_view bytes, std::string label)
      : label_(std::move(label)), memory_(bytes), size_(bytes.size()) {}

  [[nodiscard]] std::uint64_t size() const { return size_; }
  [[nodiscard]] const std::string& label() const { return label_; }

  /// Reads exactly `n` bytes at `offset` (the caller has checked the range).
  void read(std::uint64_t offset, std::size_t n, char* out) {
    if (offset > size_ || n > size_ - offset) throw InputError(label_ + ": read beyond the end");
    if (!stream_.is_open()) {
      std::memcpy(out, memory_.data() + offset, n);
      return;
    }
    stream_.clear();
    stream_.seekg(static_cast<std::streamoff>(offset));
    stream_.read(out, static_cast<std::streamsize>(n));
    if (static_cast<std::size_t>(stream_.gcount()) != n)
      throw InputError(label_ + ": read error at byte " + std::to_string(offset));
  }

  /// Offset of the next "GRIB" at or after `from`, or nullopt.
  std::optional<std::uint64_t> find(std::uint64_t from) {
    std::vector<char> chunk;
    while (from + 4 <= size_) {
      const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(kScanChunk, size_ - from));
      chunk.resize(n);
      read(from, n, chunk.data());
      static constexpr std::string_view kMagic = "GRIB";
      const auto it = std::search(chunk.begin(), chunk.end(), kMagic.begin(), kMagic.end());
      if (it != chunk.end()) return from + static_cast<std::uint64_t>(it - chunk.begin());
      if (n < 4) break;
      from += n - 3;  // a marker may straddle chunks
    }
    return std::nullopt;
  }

 private:
  std::string label_;
  std::string memory_;
  std::ifstream stream_;
  std::uint64_t size_ = 0;
};

/// An ecCodes handle over a message buffer we own.
class Handle {
 public:
  Handle(std::vector<char> bytes, const std::string& label, std::uint64_t offset)
      : bytes_(std::move(bytes)) {
    handle_ = codes_handle_new_from_message(nullptr, bytes_.data(), bytes_.size());
    if (handle_ == nullptr)
      throw InputError(label + ": GRIB message at byte " + std::to_string(offset) +
                       " cannot be decoded");
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() { codes_handle_delete(handle_); }

  [[nodiscard]] std::optional<long> integer(const char* key) const {
    long value = 0;
    if (codes_get_long(handle_, key, &value) != CODES_SUCCESS) return std::nullopt;
    return value;
  }
  [[nodiscard]] std::optional<double> number(const char* key) const {
    double value = 0.0;
    if (codes_get_double(handle_, key, &value) != CODES_SUCCESS || !std::isfinite(value))
      return std::nullopt;
    return value;
  }
  [[nodiscard]] std::string text(const char* key) const {
    std::array<char, 256> buffer{};
    std::size_t length = buffer.size();
    if (codes_get_string(handle_, key, buffer.data(), &length) != CODES_SUCCESS) return {};
    buffer.back() = '\0';
    return buffer.data();
  }
  [[nodiscard]] codes_handle* get() const { return handle_; }

 private:
  std::vector<char> bytes_;
  codes_handle* handle_ = nullptr;
};

/// One message's framing and the keys we use.
struct Message {
  std::uint64_t offset = 0;
  std::uint64_t length = 0;
  std::string name;  ///< field name (shortName, maybe with a level suffix)
  std::string shortName;
  std::string level;  ///< "typeOfLevel=level"
  FieldSummary summary;
  std::optional<UtcTime> time;
  // Grid
  long ni = 0;
  long nj = 0;
  std::array<double, 4> corners{};  ///< lat first, lon first, lat last, lon last (degrees)
  long iNegative = 0;
  std::string gridType;
  long consecutiveJ = 0;
  long alternateRows = 0;

  [[nodiscard]] bool sameGrid(const Message& o) const {
    return ni == o.ni && nj == o.nj && corners == o.corners && iNegative == o.iNegative &&
           gridType == o.gridType;
  }
};

std::uint64_t bigEndian(const unsigned char* p, int bytes) {
  std::uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v = (v << 8) | p[i];
  return v;
}

/// Validity time = reference date/time + end step. Computed here rather than with ecCodes'
/// validityDate/validityTime keys, which count through huge hostile steps one unit at a time
/// (a 1.4 KB file hung them for minutes; found by fuzzing).
std::optional<UtcTime> validity(const Handle& h) {
  const auto date = h.integer("dataDate");
  const auto time = h.integer("dataTime");
  if (!date || !time || *date < 10101 || *date > 99991231 || *time < 0 || *time > 2400)
    return std::nullopt;
  const int year = static_cast<int>(*date / 10000);
  const auto month = static_cast<unsigned>(*date / 100 % 100);
  const auto day = static_cast<unsigned>(*date % 100);
  const std::chrono::year_month_day ymd{std::chrono::year{year}, std::chrono::month{month},
                                        std::chrono::day{day}};
  const long hour = *time / 100;
  const long minute = *time % 100;
  if (!ymd.ok() || minute > 59) return std::nullopt;
  // Step units: GRIB2 code table 4.4 (ecCodes uses the same codes for GRIB1's stepUnits).
  const long units = h.integer("stepUnits").value_or(1);
  double seconds = 0.0;
  switch (units) {
    case 0: seconds = 60.0; break;
    case 1: seconds = 3600.0; break;
    case 2: seconds = 86400.0; break;
    case 10: seconds = 10800.0; break;
    case 11: seconds = 21600.0; break;
    case 12: seconds = 43200.0; break;
    case 13: case 254: seconds = 1.0; break;
    default: return std::nullopt;  // months, years, ...: not a fixed length
  }
  const double step = static_cast<double>(h.integer("endStep").value_or(0)) * seconds;
  constexpr double kMaxStepSeconds = 100.0 * 366.0 * 86400.0;  // a century of forecast
  if (!(std::abs(step) <= kMaxStepSeconds)) return std::nullopt;
  UtcTime t = UtcTime::fromCivil(year, month, day, static_cast<int>(hour), static_cast<int>(minute));
  t.unixSeconds += step;
  return t;
}

class GribGridFile final : public GridFile {
 public:
  explicit GribGridFile(ByteSource source) : source_(std::move(source)) {
    configureEccodes();
    const std::lock_guard lock(gribMutex());
    try {
      inventory();
    } catch (const GribAssertion& a) {
      fail("GRIB decoder failed: " + a.message);
    }
  }

  [[nodiscard]] const std::string& label() const override { return source_.label(); }
  [[nodiscard]] std::string format() const override { return format_; }

  [[nodiscard]] std::vector<FieldSummary> fields() const override {
    std::vector<FieldSummary> out;
    for (const auto& name : order_) out.push_back(messages_[fields_.at(name).front()].summary);
    return out;
  }

  [[nodiscard]] FieldDescription describe(const std::string& name) const override {
    const std::vector<std::size_t>& steps = stepsOf(name);
    const Message& m = messages_[steps.front()];
    FieldDescription d;
    d.summary = m.summary;
    d.geometry = geometry(m).second;
    if (steps.size() > 1 || m.time) {
      d.timeAxisName = "validity time";
      for (std::size_t s : steps) d.times.push_back(*messages_[s].time);
    }
    return d;
  }

  [[nodiscard]] LatLonGrid read(const std::string& name, std::size_t step) const override {
    const std::vector<std::size_t>& steps = stepsOf(name);
    if (step >= steps.size()) fail("field '" + name + "' has no time step " + std::to_string(step));
    const Message& m = messages_[steps[step]];
    const auto [layout, geometryGrid] = geometry(m);
    const std::lock_guard lock(gribMutex());
    try {
      return decode(m, layout, geometryGrid);
    } catch (const GribAssertion& a) {
      fail("GRIB decoder failed on field '" + name + "': " + a.message);
    }
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(source_.label() + ": " + problem);
  }

  const std::vector<std::size_t>& stepsOf(const std::string& name) const {
    const auto it = fields_.find(name);
    if (it == fields_.end()) {
      std::string known;
      for (const auto& n : order_) known += (known.empty() ? "" : ", ") + n;
      fail("no variable '" + name + "' (fields: " + known + ")");
    }
    return it->second;
  }

  void inventory();
  LatLonGrid decode(const Message& m, const GridLayout& layout, LatLonGrid grid) const;
  [[nodiscard]] std::pair<GridLayout, LatLonGrid> geometry(const Message& m) const;

  mutable ByteSource source_;
  std::string format_ = "GRIB";
  std::vector<Message> messages_;
  std::map<std::string, std::vector<std::size_t>> fields_;  ///< name -> messages by time
  std::vector<std::string> order_;                          ///< field names in file order
};

void GribGridFile::inventory() {
  std::uint64_t offset = 0;
  std::map<std::string, std::vector<std::size_t>> byShortName;
  int editions = 0;
  while (true) {
    const auto start = source_.find(offset);
    if (!start) break;
    if (*start != offset && messages_.empty() && *start > 0)
      log::info(source_.label() + ": skipping " + std::to_string(*start) +
                " bytes before the first GRIB message");
    const std::uint64_t remaining = source_.size() - *start;
    if (remaining < 16) fail("file is truncated (GRIB message at byte " + std::to_string(*start) + ")");
    std::array<unsigned char, 16> s0{};
    source_.read(*start, s0.size(), reinterpret_cast<char*>(s0.data()));
    const int edition = s0[7];
    std::uint64_t length = 0;
    if (edition == 2) {
      length = bigEndian(s0.data() + 8, 8);
    } else if (edition == 1) {
      length = bigEndian(s0.data() + 4, 3);
    } else {
      fail("GRIB message at byte " + std::to_string(*start) + " has unsupported edition " +
           std::to_string(edition));
    }
    editions |= edition;
    if (length < 16 + 4 || length > kMaxMessageBytes)
      fail("GRIB message at byte " + std::to_string(*start) + " declares an impossible length " +
           std::to_string(length));
    if (length > remaining)
      fail("file is truncated (GRIB message at byte " + std::to_string(*start) + " declares " +
           std::to_string(length) + " bytes, " + std::to_string(remaining) + " remain)");
    if (messages_.size() >= kMaxMessages)
      fail("more than " + std::to_string(kMaxMessages) + " GRIB messages");
    std::vector<char> bytes(static_cast<std::size_t>(length));
    source_.read(*start, bytes.size(), bytes.data());
    if (std::memcmp(bytes.data() + bytes.size() - 4, "7777", 4) != 0)
      fail("GRIB message at byte " + std::to_string(*start) + " does not end with '7777'");

    const Handle h(std::move(bytes), source_.label(), *start);
    Message m;
    m.offset = *start;
    m.length = length;
    m.shortName = h.text("shortName");
    if (m.shortName.empty() || m.shortName == "unknown")
      m.shortName = "param" + std::to_string(h.integer("paramId").value_or(0));
    m.level = h.text("typeOfLevel") + "=" + std::to_string(h.integer("level").value_or(0));
    m.summary.longName = h.text("name");
    m.summary.units = h.text("units");
    const std::string cf = h.text("cfName");
    m.summary.standardName = cf == "unknown" || cf == "~" ? "" : cf;
    m.time = validity(h);
    m.gridType = h.text("gridType");
    m.ni = h.integer("Ni").value_or(0);
    m.nj = h.integer("Nj").value_or(0);
    const char* cornerKeys[] = {
        "latitudeOfFirstGridPointInDegrees", "longitudeOfFirstGridPointInDegrees",
        "latitudeOfLastGridPointInDegrees", "longitudeOfLastGridPointInDegrees"};
    for (std::size_t k = 0; k < 4; ++k)
      m.corners[k] = h.number(cornerKeys[k]).value_or(std::numeric_limits<double>::quiet_NaN());
    m.iNegative = h.integer("iScansNegatively").value_or(0);
    m.consecutiveJ = h.integer("jPointsAreConsecutive").value_or(0);
    m.alternateRows = h.integer("alternativeRowScanning").value_or(0);
    byShortName[m.shortName].push_back(messages_.size());
    messages_.push_back(std::move(m));
    offset = *start + length;
  }
  if (messages_.empty()) fail("no GRIB message found");
  format_ = editions == 3 ? "GRIB1+GRIB2" : editions == 2 ? "GRIB2" : "GRIB1";

  // Field names: the shortName, or shortName@level where a shortName has several levels.
  for (auto& [shortName, indices] : byShortName) {
    std::vector<std::string> levels;
    for (std::size_t i : indices)
      if (std::find(levels.begin(), levels.end(), messages_[i].level) == levels.end())
        levels.push_back(messages_[i].level);
    for (std::size_t i : indices)
      messages_[i].name = levels.size() == 1 ? shortName : shortName + "@" + messages_[i].level;
  }
  for (std::size_t i = 0; i < messages_.size(); ++i) {
    Message& m = messages_[i];
    m.summary.name = m.name;
    auto& steps = fields_[m.name];
    if (steps.empty()) order_.push_back(m.name);
    steps.push_back(i);
  }
  for (auto& [name, steps] : fields_) {
    const Message& first = messages_[steps.front()];
    for (std::size_t s : steps) {
      const Message& m = messages_[s];
      if (!m.sameGrid(first))
        fail("field '" + name + "' changes grid between messages (bytes " +
             std::to_string(first.offset) + " and " + std::to_string(m.offset) + ")");
      if (steps.size() > 1 && !m.time)
        fail("field '" + name + "' has several messages but no valid validity date/time");
    }
    if (steps.size() > 1) {
      std::stable_sort(steps.begin(), steps.end(), [&](std::size_t a, std::size_t b) {
        return messages_[a].time->unixSeconds < messages_[b].time->unixSeconds;
      });
      for (std::size_t k = 1; k < steps.size(); ++k)
        if (messages_[steps[k]].time->unixSeconds == messages_[steps[k - 1]].time->unixSeconds)
          fail("field '" + name + "' has two messages for " +
               messages_[steps[k]].time->toIso8601() + " (ensemble members or duplicates?)");
    }
  }
}

std::pair<GridLayout, LatLonGrid> GribGridFile::geometry(const Message& m) const {
  const std::string what = "field '" + m.name + "'";
  if (m.gridType != "regular_ll")
    fail(what + " is on a '" + m.gridType +
         "' grid; only regular latitude/longitude grids (regular_ll) are supported");
  if (m.consecutiveJ != 0 || m.alternateRows != 0)
    fail(what + " uses a scanning mode other than rows of longitudes; not supported");
  for (double c : m.corners)
    if (!std::isfinite(c)) fail(what + " has no usable grid corner coordinates");
  if (m.ni < 0 || m.nj < 0) fail(what + " has a negative grid size");
  checkGridShape(source_.label(), static_cast<std::size_t>(m.nj), static_cast<std::size_t>(m.ni));
  const auto ni = static_cast<std::size_t>(m.ni);
  const auto nj = static_cast<std::size_t>(m.nj);
  std::vector<double> lat(nj);
  std::vector<double> lon(ni);
  const double dLat = (m.corners[2] - m.corners[0]) / static_cast<double>(nj - 1);
  for (std::size_t j = 0; j < nj; ++j) lat[j] = m.corners[0] + static_cast<double>(j) * dLat;
  // Longitudes may cross 0°/360° between the first and last point: the span follows the
  // scanning direction.
  double span = m.corners[3] - m.corners[1];
  if (m.iNegative == 0 && span <= 0.0) span += 360.0;
  if (m.iNegative != 0 && span >= 0.0) span -= 360.0;
  const double dLon = span / static_cast<double>(ni - 1);
  for (std::size_t i = 0; i < ni; ++i) lon[i] = m.corners[1] + static_cast<double>(i) * dLon;
  const GridLayout layout =
      planGridLayout(source_.label(), lat, "latitude", false, lon, "longitude", false);
  LatLonGrid g;
  g.name = m.name;
  g.units = m.summary.units;
  g.width = layout.width;
  g.height = layout.height;
  g.lon0Deg = layout.lon0Deg;
  g.lat0Deg = layout.lat0Deg;
  g.dLonDeg = layout.dLonDeg;
  g.dLatDeg = layout.dLatDeg;
  g.wrapsLongitude = layout.wrapsLongitude;
  return {layout, g};
}

LatLonGrid GribGridFile::decode(const Message& m, const GridLayout& layout, LatLonGrid grid) const {
  const std::string what = "field '" + m.name + "'";
  std::vector<char> bytes(static_cast<std::size_t>(m.length));
  source_.read(m.offset, bytes.size(), bytes.data());
  const Handle h(std::move(bytes), source_.label(), m.offset);
  const auto ni = static_cast<std::size_t>(m.ni);
  const auto nj = static_cast<std::size_t>(m.nj);
  std::size_t count = 0;
  if (codes_get_size(h.get(), "values", &count) != CODES_SUCCESS || count != ni * nj)
    fail(what + " holds " + std::to_string(count) + " values for a " + std::to_string(ni) + " x " +
         std::to_string(nj) + " grid");
  std::vector<double> values(count);
  std::size_t got = count;
  const int status = codes_get_double_array(h.get(), "values", values.data(), &got);
  if (status != CODES_SUCCESS || got != count)
    fail(what + " cannot be decoded (" + codes_get_error_message(status) + ")");
  const bool bitmap = h.integer("bitmapPresent").value_or(0) != 0;
  const double missing = h.number("missingValue").value_or(9999.0);

  const auto width = static_cast<std::size_t>(layout.width);
  grid.values.assign(nj * width, std::numeric_limits<float>::quiet_NaN());
  constexpr double kFloatMax = static_cast<double>(std::numeric_limits<float>::max());
  std::size_t valid = 0;
  for (std::size_t r = 0; r < nj; ++r) {
    float* out = grid.values.data() + layout.outputRow(r) * width;
    const double* in = values.data() + r * ni;
    for (std::size_t c = 0; c < width; ++c) {
      const double v = in[layout.fileColumn(c, ni)];
      if (std::isnan(v) || (bitmap && v == missing)) continue;
      if (!std::isfinite(v) || std::abs(v) > kFloatMax)
        fail(what + " has a non-finite or out-of-range value");
      out[c] = static_cast<float>(v);
      ++valid;
    }
  }
  if (valid == 0) fail(what + " holds no data (every value is missing)");
  return grid;
}

}  // namespace

bool looksLikeGrib(std::string_view head) { return head.substr(0, 4) == "GRIB"; }

std::unique_ptr<GridFile> openGrib(const fs::path& file) {
  return std::make_unique<GribGridFile>(ByteSource(file, file.string()));
}

std::unique_ptr<GridFile> openGribMemory(std::string_view bytes, const std::string& label) {
  return std::make_unique<GribGridFile>(ByteSource(bytes, label));
}

}  // namespace og::data::detail
