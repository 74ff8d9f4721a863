/**
 * @file file_hash.h
 * A fingerprint of a file's bytes (64-bit FNV-1a, as 16 hex digits): to
 * detect a damaged checkpoint and a changed RVE template or packing on
 * --resume. Not cryptographic; it guards against accidents.
 */
#pragma once

#include <cstddef>
#include <string>

namespace fe2dem::macro
{
/// FNV-1a 64 of the bytes of @p file, 16 hex digits; "" if it cannot be read.
std::string file_hash(const std::string& file);
/// FNV-1a 64 of @p size bytes at @p data (file_hash of a file holding them).
std::string bytes_hash(const char* data, std::size_t size);
} // namespace fe2dem::macro
