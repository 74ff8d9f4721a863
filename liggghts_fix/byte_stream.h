/**
 * @file byte_stream.h
 * Minimal binary writer/reader for state that must survive a LIGGGHTS
 * restart or travel between MPI ranks: trivially copyable values, vectors
 * of them, and strings. Same machine, same build: no endianness handling.
 */
#pragma once

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace fe2dem
{
class ByteWriter
{
public:
  template <class T>
  void put(const T& v)
  {
    static_assert(std::is_trivially_copyable_v<T>, "put() takes trivially copyable values");
    const char* p = reinterpret_cast<const char*>(&v);
    bytes_.insert(bytes_.end(), p, p + sizeof(T));
  }
  template <class T>
  void put(const std::vector<T>& v)
  {
    put(static_cast<std::uint64_t>(v.size()));
    for (const T& x : v)
      put(x);
  }
  void put(const std::string& s)
  {
    put(static_cast<std::uint64_t>(s.size()));
    bytes_.insert(bytes_.end(), s.begin(), s.end());
  }
  /// Same call for writing and reading: see ByteReader::io.
  template <class T>
  void io(const T& v)
  {
    put(v);
  }
  const std::vector<char>& bytes() const { return bytes_; }

private:
  std::vector<char> bytes_;
};

class ByteReader
{
public:
  ByteReader(const char* data, std::size_t size) : p_(data), end_(data + size) {}
  template <class T>
  void get(T& v)
  {
    static_assert(std::is_trivially_copyable_v<T>, "get() takes trivially copyable values");
    need(sizeof(T));
    std::memcpy(&v, p_, sizeof(T));
    p_ += sizeof(T);
  }
  template <class T>
  void get(std::vector<T>& v)
  {
    std::uint64_t n = 0;
    get(n);
    v.resize(n);
    for (T& x : v)
      get(x);
  }
  void get(std::string& s)
  {
    std::uint64_t n = 0;
    get(n);
    need(n);
    s.assign(p_, p_ + n);
    p_ += n;
  }
  /// Same call for writing and reading, so that one field list serves both.
  template <class T>
  void io(T& v)
  {
    get(v);
  }
  bool at_end() const { return p_ == end_; }

private:
  void need(std::size_t n) const
  {
    if (static_cast<std::size_t>(end_ - p_) < n)
      throw std::runtime_error("truncated state record");
  }
  const char* p_;
  const char* end_;
};
} // namespace fe2dem
