// The byte format of a remote call between the grading judge and its worker (framework/remote/).
//
// Values cross as plain bytes: trivially copyable types as they are in memory (both processes
// are built from one tree by one compiler), containers as a count and their elements. A Reader
// never trusts what it reads: a size larger than what is left, or a read past the end, marks it
// failed and yields zeros, so a lying or crashing worker can give the judge wrong values but
// never make it read out of bounds.
#pragma once

#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace rt::remote {

class Writer {
  public:
    Writer() = default;
    // A writer that keeps only a hash of what it is given (XXH3, 64 bits): how the judge tells
    // whether the worker already holds a scene, without copying it.
    struct HashOnly {};
    explicit Writer(HashOnly);
    ~Writer();
    Writer(const Writer&) = delete;
    Writer& operator=(const Writer&) = delete;

    void bytes(const void* data, std::size_t size) {
        if (hash_)
            update_hash(data, size);
        else
            bytes_.append(static_cast<const char*>(data), size);
    }
    std::uint64_t digest() const;
    template <class T>
    void pod(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(&value, sizeof value);
    }
    std::string& data() { return bytes_; }

  private:
    void update_hash(const void* data, std::size_t size);
    std::string bytes_;
    void* hash_ = nullptr;  // XXH3_state_t
};

class Reader {
  public:
    explicit Reader(std::string_view data) : data_(data) {}
    void bytes(void* out, std::size_t size) {
        if (!ok_ || size > data_.size() - at_) {
            ok_ = false;
            std::memset(out, 0, size);
            return;
        }
        std::memcpy(out, data_.data() + at_, size);
        at_ += size;
    }
    template <class T>
    void pod(T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(&value, sizeof value);
    }
    // A count of elements of `element_size` bytes each: 0 (and failed) when they cannot follow.
    std::size_t count(std::size_t element_size) {
        std::uint64_t n = 0;
        pod(n);
        if (element_size > 0 && n > (data_.size() - at_) / element_size) {
            ok_ = false;
            return 0;
        }
        return std::size_t(n);
    }
    bool ok() const { return ok_; }
    bool at_end() const { return at_ == data_.size(); }
    void fail() { ok_ = false; }

  private:
    std::string_view data_;
    std::size_t at_ = 0;
    bool ok_ = true;
};

// A bool read from untrusted bytes holds 0 or 1 afterwards (any other byte would be undefined).
inline void normalize(bool& b) {
    unsigned char c;
    std::memcpy(&c, &b, 1);
    b = c != 0;
}

// The codec of a type: put/get. Trivially copyable types by default; the others (and the
// trivially copyable ones that hold pointers or bools) overload put/get in wire_types.h.
// Set for each type that names its fields (RT_WIRE_FIELDS, wire_types.h): it crosses field by
// field even when trivially copyable, so its bools are checked on the way in.
template <class T>
inline constexpr bool kFieldByField = false;
// Set for the trivially copyable structs with bools that cross per ray (RT_WIRE_BOOLS,
// wire_types.h): they cross as bytes, and each named bool is made 0 or 1 on the way in.
template <class T>
inline constexpr bool kBytesWithBools = false;
template <class T>
concept PlainBytes = std::is_trivially_copyable_v<T> && !std::is_pointer_v<T> &&
                     !kFieldByField<T> && !kBytesWithBools<T>;

template <PlainBytes T>
void put(Writer& w, const T& value) {
    w.pod(value);
}
template <PlainBytes T>
void get(Reader& r, T& value) {
    r.pod(value);
}
inline void get(Reader& r, bool& value) {
    r.pod(value);
    normalize(value);
}

inline void put(Writer& w, const std::string& s) {
    w.pod(std::uint64_t(s.size()));
    w.bytes(s.data(), s.size());
}
inline void get(Reader& r, std::string& s) {
    s.resize(r.count(1));
    r.bytes(s.data(), s.size());
}

template <class T>
void put(Writer& w, const std::vector<T>& v) {
    w.pod(std::uint64_t(v.size()));
    if constexpr (PlainBytes<T> && !std::is_same_v<T, bool>)
        w.bytes(v.data(), v.size() * sizeof(T));
    else
        for (const T& x : v) put(w, x);
}
template <class T>
void get(Reader& r, std::vector<T>& v) {
    if constexpr (PlainBytes<T> && !std::is_same_v<T, bool>) {
        v.resize(r.count(sizeof(T)));
        r.bytes(v.data(), v.size() * sizeof(T));
    } else {
        v.resize(r.count(1));
        for (T& x : v) get(r, x);
    }
}

}  // namespace rt::remote
