#include "remote/connection.h"

#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>

namespace rt::remote {
namespace {

bool write_all(int fd, const char* data, std::size_t size) {
    while (size > 0) {
        const ssize_t n = ::send(fd, data, size, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        data += n;
        size -= std::size_t(n);
    }
    return true;
}

bool read_all(int fd, char* data, std::size_t size) {
    while (size > 0) {
        const ssize_t n = ::read(fd, data, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        data += n;
        size -= std::size_t(n);
    }
    return true;
}

}  // namespace

// The size and the payload in one send: the peer wakes once per message, not twice.
bool send_message(int fd, const std::string& payload) {
    const std::uint64_t size = payload.size();
    std::string message(reinterpret_cast<const char*>(&size), sizeof size);
    message += payload;
    return write_all(fd, message.data(), message.size());
}

bool receive_message(int fd, std::string& payload) {
    std::uint64_t size = 0;
    if (!read_all(fd, reinterpret_cast<char*>(&size), sizeof size) || size > kMaxMessage)
        return false;
    payload.resize(std::size_t(size));
    return read_all(fd, payload.data(), payload.size());
}

}  // namespace rt::remote
