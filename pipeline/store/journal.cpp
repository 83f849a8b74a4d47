#include "store/journal.hpp"

#include <cerrno>
#include <charconv>
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <cstring>
#include <istream>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <ext/stdio_filebuf.h>
#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include "core/line_reader.hpp"
#include "durable_file.hpp"
#include "store/checked_line.hpp"
#include "store/content_hash.hpp"

namespace lc::farm {

namespace {

constexpr const char* header = "lightcone-journal 1";


// A journal number: every one is a count, a size, seconds or a time, so
// at least 0, and finite (std::from_chars reads "nan" and "inf", which a
// later comparison would let through).
template <class T>
bool parse_number(const std::string& s, T& out) {
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  if (ec != std::errc() || p != s.data() + s.size()) return false;
  if constexpr (std::is_floating_point_v<T>)
    if (!std::isfinite(out)) return false;
  return out >= T{0};
}

// key=value tokens separated by single spaces; nullopt when one is malformed.
std::optional<std::map<std::string, std::string>> fields(const std::string& content) {
  std::map<std::string, std::string> out;
  std::istringstream in(content);
  std::string token;
  while (in >> token) {
    const auto eq = token.find('=');
    if (eq == std::string::npos || eq == 0) return std::nullopt;
    out[token.substr(0, eq)] = token.substr(eq + 1);
  }
  return out;
}

// The delivery's fields of a frame line (delivery_fields), `get` a field's
// value or null, into `d`; false when one is malformed or out of range.
// Absent fields are the defaults (older lines, or a plain delivery).
template <class Get>
bool parse_delivery(const Get& get, Delivery& d) {
  if (const std::string* camera = get("camera")) {
    const auto named = delivery_named(*camera);
    if (!named || *named == DeliveryCamera::shot) return false;  // the shot's own is never written
    d.camera = *named;
  }
  // A number of the delivery within [lo, hi] (open at lo where `above`).
  auto number = [&](const char* key, double& out, double lo, double hi, bool above) {
    const std::string* text = get(key);
    if (!text) return true;
    double v = 0.0;
    if (!parse_number(*text, v) || v < lo || v > hi || (above && v == lo)) return false;
    out = v;
    return true;
  };
  const double no_limit = std::numeric_limits<double>::max();
  if (!number("dome_tilt", d.dome_tilt, 0.0, max_dome_angle, false) ||
      !number("dome_elevation", d.dome_elevation, 0.0, max_dome_angle, false) ||
      !number("separation", d.separation, 0.0, no_limit, true))
    return false;
  if (const std::string* sky = get("sky_catalogue")) {
    if (*sky != name_of(DeliverySky::kstars)) return false;
    d.sky = DeliverySky::kstars;
  }
  return true;
}

// The makers' fields of a frame line (makers_fields), `get` a field's value
// or null, into `m`; false when one is malformed.  Absent: not recorded.
template <class Get>
bool parse_makers(const Get& get, FrameMakers& m) {
  const std::string *ranks = get("ranks"), *nodes = get("nodes"), *count = get("rank_count");
  if (!ranks && !nodes && !count) return true;
  if (!ranks || !nodes) return false;
  // Every piece between commas, empty ones too (a node without a name).
  auto pieces = [](const std::string& list) {
    std::vector<std::string> out(1);
    for (const char c : list)
      if (c == ',')
        out.emplace_back();
      else
        out.back() += c;
    return out;
  };
  const std::vector<std::string> rank_list = pieces(*ranks), node_list = pieces(*nodes);
  if (rank_list.size() != node_list.size() || rank_list.size() > max_listed_ranks) return false;
  for (std::size_t k = 0; k < rank_list.size(); ++k) {
    FrameMakers::Rank r;
    if (!parse_number(rank_list[k], r.rank) || (k > 0 && r.rank <= m.ranks.back().rank)) return false;
    r.node = percent_decode(node_list[k]);
    m.ranks.push_back(std::move(r));
  }
  m.count = static_cast<int>(m.ranks.size());
  if (count && (!parse_number(*count, m.count) || m.count <= static_cast<int>(m.ranks.size()))) return false;
  return true;
}

// " ranks=1,2 nodes=a,b [rank_count=N]" of a frame line; "" when not recorded.
std::string makers_fields(const FrameMakers& m) {
  if (m.ranks.empty()) return "";
  std::string ranks, nodes;
  for (const FrameMakers::Rank& r : m.ranks) {
    if (!ranks.empty()) {
      ranks += ',';
      nodes += ',';
    }
    ranks += std::to_string(r.rank);
    // A host name is letters, digits, '-' and '.'; whatever else, and the
    // list's comma, is escaped, so any name reads back.
    nodes += percent_encode(r.node, ",");
  }
  const int count = std::max(m.count, static_cast<int>(m.ranks.size()));
  return fmt::format(" ranks={} nodes={}{}", ranks, nodes,
                     count > static_cast<int>(m.ranks.size()) ? fmt::format(" rank_count={}", count) : "");
}

// A frame line's fields -> JournalFrame; nullopt when any field is missing
// or malformed (e.g. written by a newer lightcone).
std::optional<JournalFrame> parse_frame(const std::string& content) {
  const auto f = fields(content);
  if (!f) return std::nullopt;
  auto get = [&](const char* k) -> const std::string* {
    auto it = f->find(k);
    return it == f->end() ? nullptr : &it->second;
  };
  JournalFrame jf;
  const std::string *frame = get("frame"), *size = get("size"), *ss = get("supersample"), *layers = get("layers"),
                    *inputs = get("inputs"), *exr = get("exr"), *png = get("png"), *rays = get("rays");
  if (!frame || !size || !ss || !layers || !inputs || !exr || !png || !rays) return std::nullopt;
  const auto x = size->find('x');
  if (x == std::string::npos) return std::nullopt;
  if (!parse_number(*frame, jf.frame) || !parse_number(size->substr(0, x), jf.settings.width) ||
      !parse_number(size->substr(x + 1), jf.settings.height) || !parse_number(*ss, jf.settings.supersample) ||
      !parse_number(*exr, jf.exr_bytes) || !parse_number(*png, jf.png_bytes) || !parse_number(*rays, jf.cost.rays))
    return std::nullopt;
  if (jf.settings.width < 1 || jf.settings.height < 1 || jf.settings.supersample < 1) return std::nullopt;
  if (*layers != "0" && *layers != "1") return std::nullopt;
  jf.settings.layers = *layers == "1";
  // Written since adaptive supersampling; older lines sampled the full grid.
  if (const std::string* sampling = get("sampling")) {
    if (*sampling != "adaptive" && *sampling != "full") return std::nullopt;
    jf.settings.adaptive = *sampling == "adaptive";
  }
  if (const std::string* depth = get("png_depth")) {
    if (*depth != "16") return std::nullopt;  // 8 is never written
    jf.settings.png_depth = PngDepth::sixteen;
  }
  if (!parse_delivery(get, jf.settings.delivery)) return std::nullopt;
  if (const std::string* region = get("region")) {
    ImageWindow& w = jf.settings.window;
    const auto c1 = region->find(','), c2 = region->find(',', c1 + 1), x = region->find('x', c2 + 1);
    if (c1 == std::string::npos || c2 == std::string::npos || x == std::string::npos ||
        !parse_number(region->substr(0, c1), w.x0) || !parse_number(region->substr(c1 + 1, c2 - c1 - 1), w.y0) ||
        !parse_number(region->substr(c2 + 1, x - c2 - 1), w.frame_width) ||
        !parse_number(region->substr(x + 1), w.frame_height) || w.frame_width < 1 || w.frame_height < 1)
      return std::nullopt;
  }
  // Written where the command line set the shutter (render --shutter ...).
  if (const std::string* open = get("shutter")) {
    double v = 0.0;
    if (!parse_number(*open, v) || v > 1.0) return std::nullopt;
    jf.settings.shutter.open = v;
  }
  if (const std::string* position = get("shutter_position")) {
    const auto names = choice_names(ShutterPosition{});
    const auto it = std::find(names.begin(), names.end(), *position);
    if (it == names.end()) return std::nullopt;
    jf.settings.shutter.position = static_cast<ShutterPosition>(it - names.begin());
  }
  if (const std::string* samples = get("time_samples")) {
    int v = 0;
    if (!parse_number(*samples, v) || v < 1 || v > max_time_samples) return std::nullopt;
    jf.settings.shutter.time_samples = v;
  }
  if (inputs->size() != 16) return std::nullopt;
  jf.inputs = *inputs;
  // Written since encode checks for stale frames (both, or neither).
  if (const std::string* script = get("script")) {
    if (script->size() != 16) return std::nullopt;
    jf.parts.script = *script;
    if (const std::string* sky = get("sky")) {
      // One hash a file ("+" between them): sizes 16, 33, 50, ...
      if (sky->size() % 17 != 16) return std::nullopt;
      for (std::size_t k = 16; k < sky->size(); k += 17)
        if ((*sky)[k] != '+') return std::nullopt;
      jf.parts.sky = *sky;
    }
  }
  // Written since the journal records what a frame cost (all four, or none).
  if (const std::string* reused = get("reused")) {
    const std::string *core = get("core_seconds"), *stars = get("star_seconds"), *finished = get("finished");
    if (!core || !stars || !finished || !parse_number(*reused, jf.cost.reused) ||
        !parse_number(*core, jf.cost.core_seconds) || !parse_number(*stars, jf.cost.star_seconds) ||
        !parse_number(*finished, jf.cost.finished))
      return std::nullopt;
  }
  // Written since the monitor shows who made a frame and how long it took.
  if (const std::string* wall = get("wall_seconds"))
    if (!parse_number(*wall, jf.cost.wall_seconds)) return std::nullopt;
  if (!parse_makers(get, jf.makers)) return std::nullopt;
  // Written where the PNG has a look of its own, and where a develop gave
  // it another than the render's.
  try {
    if (const std::string* look = get("look")) jf.look = parse_look_text(*look);
    if (const std::string* look = get("render_look")) jf.render_look = parse_look_text(*look);
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
  return jf;
}

}  // namespace

std::string delivery_fields(const Delivery& d) {
  // Each only where not the default, so a plain dome's line reads as before.
  std::string out;
  if (d.camera != DeliveryCamera::shot) out += fmt::format(" camera={}", name_of(d.camera));
  if (d.dome_tilt != default_dome_tilt) out += fmt::format(" dome_tilt={}", d.dome_tilt);
  if (d.dome_elevation != default_dome_elevation) out += fmt::format(" dome_elevation={}", d.dome_elevation);
  if (d.separation != default_ods_separation) out += fmt::format(" separation={}", d.separation);
  if (d.sky != DeliverySky::shot) out += fmt::format(" sky_catalogue={}", name_of(d.sky));
  return out;
}

std::string journal_header_line() { return with_check(header); }

std::string journal_frame_line(const JournalFrame& f) {
  // The parts go only where known (a sky only with a script, as parse_frame reads them).
  const std::string parts = f.parts.script.empty() ? ""
                            : " script=" + f.parts.script + (f.parts.sky.empty() ? "" : " sky=" + f.parts.sky);
  const FrameCost& c = f.cost;
  const std::string cost = c.recorded() ? fmt::format(" reused={} core_seconds={:.3f} star_seconds={:.3f} finished={}",
                                                      c.reused, c.core_seconds, c.star_seconds, c.finished)
                                        : "";
  // png_depth only where not 8, so 8-bit lines read the same in an older lightcone.
  const ImageWindow& w = f.settings.window;
  const std::string depth = std::string(f.settings.png_depth == PngDepth::sixteen ? " png_depth=16" : "") +
                            (w.windowed() ? fmt::format(" region={},{},{}x{}", w.x0, w.y0, w.frame_width, w.frame_height)
                                          : "") +
                            delivery_fields(f.settings.delivery) +
                            (f.settings.shutter.open ? fmt::format(" shutter={}", *f.settings.shutter.open) : "") +
                            (f.settings.shutter.position
                                 ? fmt::format(" shutter_position={}", choice_name(*f.settings.shutter.position))
                                 : "") +
                            (f.settings.shutter.time_samples
                                 ? fmt::format(" time_samples={}", *f.settings.shutter.time_samples)
                                 : "");
  const std::string made = (c.wall_seconds >= 0.0 ? fmt::format(" wall_seconds={:.3f}", c.wall_seconds) : "") +
                           makers_fields(f.makers);
  const std::string look = look_text(f.look);
  const std::string render_look =
      f.render_look && !(*f.render_look == f.look) ? " render_look=" + look_text(*f.render_look) : "";
  return with_check(fmt::format("frame={} size={}x{} supersample={} layers={} sampling={}{} inputs={}{} exr={} png={} rays={}{}{}{}{}",
                                f.frame, f.settings.width, f.settings.height, f.settings.supersample,
                                f.settings.layers ? 1 : 0, f.settings.adaptive ? "adaptive" : "full", depth, f.inputs, parts,
                                f.exr_bytes, f.png_bytes, c.rays, cost, made, look.empty() ? "" : " look=" + look, render_look));
}

std::string journal_input_line(const std::string& hash, const std::string& path) {
  return with_check(fmt::format("input hash={} path={}", hash, path));
}

// Walks complete lines, one at a time in bounded memory (a junk line of
// any length costs max_journal_line bytes); keeps those whose check holds.
// The first complete line must be the header, else the file is not ours.
JournalContents parse_journal(std::istream& in, const std::string& name) {
  JournalContents out;
  LineReader lines(in, max_journal_line);
  std::uintmax_t pos = 0;
  bool first = true;
  while (const auto text = lines.next()) {
    if (!text->complete) {
      out.torn_tail = true;
      break;
    }
    pos += text->bytes;
    // An overlong line is no line this lightcone wrote: a bad line, as one
    // whose check fails.
    const std::optional<std::string> content =
        text->too_long ? std::nullopt : checked_content(std::string(text->text));
    if (first) {
      first = false;
      if (!content || *content != header)
        throw std::runtime_error(fmt::format(
            "{} is not a lightcone journal (its first line is '{}'); move it away or choose another --out", name,
            text->text.substr(0, 60)));
      out.valid_bytes = pos;
      continue;
    }
    if (!content) {
      ++out.bad_lines;
      continue;
    }
    if (content->rfind("input ", 0) == 0) {
      const auto h = content->find("hash="), p = content->find(" path=");
      if (h == std::string::npos || p == std::string::npos || p < h + 5) {
        ++out.bad_lines;
        continue;
      }
      out.inputs[content->substr(p + 6)] = content->substr(h + 5, p - h - 5);
    } else if (auto jf = parse_frame(*content)) {
      out.frames[jf->frame] = *jf;
      out.last_frame = jf->frame;
    } else {
      ++out.bad_lines;
      continue;
    }
    out.valid_bytes = pos;
  }
  if (lines.failed()) throw std::runtime_error(fmt::format("cannot read {}: a read error", name));
  // A bad line after the last good one is a torn tail too: cut it off.
  return out;
}

JournalContents parse_journal(const std::string& text, const std::string& name) {
  std::istringstream in(text, std::ios::binary);
  return parse_journal(in, name);
}

StaleFrames stale_frames(const JournalContents& journal, const std::map<int, std::uintmax_t>& png_sizes) {
  StaleFrames out;
  if (journal.last_frame < 0 || png_sizes.empty()) return out;
  const JournalFrame& latest = journal.frames.at(journal.last_frame);
  std::set<std::string> latest_hashes;  // of every input file, as the last render to see it recorded it
  for (const auto& [path, hash] : journal.inputs) latest_hashes.insert(hash);
  // Why `jf` was made otherwise than the latest render, as the list it goes in.
  auto made_otherwise = [&](const JournalFrame& jf) -> std::vector<int>* {
    if (!(jf.settings == latest.settings)) return &out.other_settings;
    if (jf.parts.script.empty() || latest.parts.script.empty())
      return jf.inputs == latest.inputs ? nullptr : &out.earlier_script;
    if (jf.parts.script != latest.parts.script) return &out.earlier_script;
    for (std::size_t k = 0; k + 16 <= jf.parts.sky.size(); k += 17)
      if (!latest_hashes.count(jf.parts.sky.substr(k, 16))) return &out.earlier_sky;
    return nullptr;
  };
  for (const auto& [frame, bytes] : png_sizes) {
    const auto it = journal.frames.find(frame);
    if (it == journal.frames.end() || it->second.png_bytes != bytes)
      out.unrecorded.push_back(frame);
    else if (std::vector<int>* list = made_otherwise(it->second))
      list->push_back(frame);
  }
  const int first = png_sizes.begin()->first, last = png_sizes.rbegin()->first;
  for (auto it = journal.frames.lower_bound(first); it != journal.frames.end() && it->first <= last; ++it)
    if (!png_sizes.count(it->first) && !made_otherwise(it->second)) out.absent.push_back(it->first);
  return out;
}

JournalContents read_journal(const std::filesystem::path& file) {
  // Opened as lightcone's own file: a FIFO under the journal's name would
  // block the read for good (a render holding the folder's lock), a link
  // would lead to another folder's journal.
  const OwnFile own = open_own_file(file, O_RDONLY, "read the journal");
  if (own.fd < 0) return {};
  __gnu_cxx::stdio_filebuf<char> buffer(own.fd, std::ios::in | std::ios::binary);  // closes the descriptor
  std::istream in(&buffer);
  return parse_journal(in, file.string());
}

JournalWriter::JournalWriter(std::filesystem::path file, std::uintmax_t valid_bytes)
    : file_(std::move(file)), valid_bytes_(valid_bytes) {}

JournalWriter::~JournalWriter() {
  if (fd_ >= 0) ::close(fd_);
}

namespace {
[[noreturn]] void fail(const std::filesystem::path& p, const char* what) {
  throw std::runtime_error(fmt::format("cannot {} the journal {}: {}", what, p.string(), std::strerror(errno)));
}

// Writes all of `data` (write() may write less than asked).
void write_all(int fd, const std::string& data, const std::filesystem::path& p) {
  std::size_t done = 0;
  while (done < data.size()) {
    const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail(p, "write");
    }
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace

// Opens (creating with the header, or cutting a torn tail) on first use,
// as lightcone's own file: never through a link (which would append to
// another folder's journal), never a FIFO.
void JournalWriter::open() {
  const OwnFile own = open_own_file(file_, O_WRONLY | O_CREAT, "write the journal");
  fd_ = own.fd;
  const bool existed = !own.created;
  if (::ftruncate(fd_, static_cast<off_t>(existed ? valid_bytes_ : 0)) != 0) fail(file_, "truncate");
  if (::lseek(fd_, 0, SEEK_END) < 0) fail(file_, "seek in");
  if (!existed || valid_bytes_ == 0) {
    write_all(fd_, journal_header_line() + "\n", file_);
    if (::fsync(fd_) != 0) fail(file_, "sync");
    sync_directory(file_.parent_path());  // the new name, too, must survive a crash
  }
}

void JournalWriter::append(const std::string& line) {
  if (fd_ < 0) open();
  const off_t before = ::lseek(fd_, 0, SEEK_END);
  try {
    write_all(fd_, line + "\n", file_);
    if (::fsync(fd_) != 0) fail(file_, "sync");
  } catch (...) {
    // Take back a partial line (a full disk) so the file stays clean; if
    // even that fails, readers skip the torn line anyway.
    if (before >= 0 && ::ftruncate(fd_, before) == 0) ::fsync(fd_);
    throw;
  }
}

}  // namespace lc::farm
