// nbscope io: what nbscope and a plugin's host process (io/plugin_host.hpp) say to each other over
// their socket: a frame to detect, and what the detection gave (pairs, cells, walk check, the first
// misbehaviour, the trace). Each message is a 64-bit length and that many bytes, written by one
// build of nbscope and read by the same build: no versioning, no byte-order swaps.
//
// Index: WireWriter, WireReader | DetectRequest, DetectReply | encode/decode | send/receive.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/detector.hpp"
#include "core/elements.hpp"
#include "core/trace.hpp"

namespace nbscope {

// Appends plain values, arrays of them and texts to one buffer.
class WireWriter {
 public:
  template <class T>
  void value(const T& v) { raw(&v, sizeof v); }
  template <class T>
  void array(const T* data, std::size_t count) {
    value(static_cast<std::uint64_t>(count));
    raw(data, count * sizeof(T));
  }
  void text(std::string_view s) { array(s.data(), s.size()); }
  void raw(const void* data, std::size_t bytes);
  // Empties the buffer, keeping its memory for the next message, and makes room for `bytes`.
  void restart(std::size_t bytes) {
    bytes_.clear();
    bytes_.reserve(bytes);
  }
  [[nodiscard]] std::vector<char>& bytes() { return bytes_; }

 private:
  std::vector<char> bytes_;
};

// Reads what a WireWriter wrote; throws Error("plugin host: ...") when the bytes run out.
class WireReader {
 public:
  WireReader(const char* data, std::size_t size) : at_(data), end_(data + size) {}
  template <class T>
  T value() {
    T v;
    raw(&v, sizeof v);
    return v;
  }
  template <class T>
  void array(std::vector<T>& out) {
    out.resize(count(sizeof(T)));
    raw(out.data(), out.size() * sizeof(T));
  }
  std::string text();
  void raw(void* out, std::size_t bytes);
  // The next count, checked against the bytes left for `each`-byte items.
  std::size_t count(std::size_t each);

 private:
  const char* at_;
  const char* end_;
};

// One frame to detect, as the host's PluginDetector is to be called.
struct DetectRequest {
  Elements elements;  // decoded only: the sender encodes its own (open space: a plugin refuses a box)
  DetectOptions options;
  bool traced = false;
  bool keep_tests = true;            // TraceLog::keeps_tests of the caller's log
  std::int64_t operation_limit = 0;  // PluginDetector::set_operation_limit (0: its default)
};

// The kinds of error a detection may throw, carried across as themselves.
enum class WireError : std::uint8_t { none, error, plugin_error, detector_bug };

// What one detection gave.
struct DetectReply {
  WireError error = WireError::none;
  std::string message;  // the error's what()
  PairList pairs;
  bool has_cells = false;
  std::vector<CellIndex> cells;
  bool walks_checked = false;
  WalkCheck walks;
  std::optional<Misbehaviour> misbehaviour;
};

// The first byte of every message nbscope sends: what it asks.
enum class HostRequest : std::uint8_t { detect = 'D', own_bytes = 'B' };

// The request as bytes, and back.
void encode(const Elements& elements, const DetectRequest& request, WireWriter& out);
DetectRequest decode_request(WireReader& in);
// The reply and the call's trace (null: untraced) as bytes, and back: the trace's arrays declared and
// its events appended to `trace` (when not null; reset first), their labels interned (intern_plugin_label),
// through `events` (memory kept between calls).
void encode(const DetectReply& reply, const TraceLog* trace, WireWriter& out);
void decode_reply(WireReader& in, DetectReply& reply, TraceLog* trace, std::vector<TraceEvent>& events);

// Writes one message (its length, then `bytes`) to `fd`; false when the other end is gone.
bool send_message(int fd, const std::vector<char>& bytes);
// Reads one whole message from a blocking `fd`; false at its end (the other process is gone).
bool receive_message(int fd, std::vector<char>& bytes);

}  // namespace nbscope
