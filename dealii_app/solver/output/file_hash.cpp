#include "output/file_hash.h"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <vector>

namespace fe2dem::macro
{
namespace
{
constexpr std::uint64_t fnv_offset_basis = 14695981039346656037ull;

std::uint64_t add_bytes(std::uint64_t h, const char* data, std::size_t size)
{
  for (std::size_t i = 0; i < size; ++i)
    h = (h ^ static_cast<unsigned char>(data[i])) * 1099511628211ull; // FNV prime
  return h;
}

std::string hex(std::uint64_t h)
{
  char digits[17];
  std::snprintf(digits, sizeof digits, "%016llx", static_cast<unsigned long long>(h));
  return digits;
}
} // namespace

std::string file_hash(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  if (!in)
    return "";
  std::uint64_t h = fnv_offset_basis;
  std::vector<char> buffer(1 << 20);
  while (in)
  {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    h = add_bytes(h, buffer.data(), static_cast<std::size_t>(in.gcount()));
  }
  return hex(h);
}

std::string bytes_hash(const char* data, const std::size_t size)
{
  return hex(add_bytes(fnv_offset_basis, data, size));
}
} // namespace fe2dem::macro
