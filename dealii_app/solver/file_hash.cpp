#include "file_hash.h"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <vector>

namespace fe2dem::macro
{
std::string file_hash(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  if (!in)
    return "";
  std::uint64_t h = 14695981039346656037ull; // FNV-1a offset basis
  std::vector<char> buffer(1 << 20);
  while (in)
  {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    for (std::streamsize i = 0; i < in.gcount(); ++i)
      h = (h ^ static_cast<unsigned char>(buffer[i])) * 1099511628211ull; // FNV prime
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}
} // namespace fe2dem::macro
