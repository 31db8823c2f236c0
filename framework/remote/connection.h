// One end of the judge-worker socket: length-prefixed messages (framework/remote/).
#pragma once

#include <cstdint>
#include <string>

namespace rt::remote {

// The largest message either side accepts: a whole rendered image of a graded scene fits.
inline constexpr std::size_t kMaxMessage = std::size_t(1) << 30;

// The first byte of every message from the worker: the call's result, the exception it threw
// (then its message), or a callback the worker needs from the judge first.
enum Status : std::uint8_t { kDone = 0, kThrew = 1, kCallback = 2 };

// Sends one message; false when the peer is gone.
bool send_message(int fd, const std::string& payload);
// Keeps memory freed after large messages for the next one instead of returning it to the
// kernel; both ends call it once, before their first message.
void keep_freed_memory();
// Receives one message; false at end of stream, on error or when it is larger than kMaxMessage.
bool receive_message(int fd, std::string& payload);

}  // namespace rt::remote
