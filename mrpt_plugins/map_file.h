// Map files on disk. A map file is an MRPT-serialized object followed by a 12-byte trailer: the
// eight bytes "NVMAPCRC" and the CRC-32 (zlib's, little-endian) of every byte before it, so that
// a changed byte anywhere is an error naming the file instead of a map that loads with a wrong
// value. MRPT's reader stops at the object's end marker: the trailer changes nothing for it. A
// file without the trailer (saved by an earlier version, or gzip'd) loads unchecked, as before.
#pragma once

#include <mrpt/serialization/CSerializable.h>

#include <string>

namespace novelty::mrpt_plugins {

/// Serializes `object` to `path` with its checksum, through a new temporary file
/// (core::TemporaryFile: synced, then renamed): a process killed at any moment, or a full disk,
/// leaves `path` the old map or the new.
void SaveAtomically(const mrpt::serialization::CSerializable& object, const std::string& path);

/// Deserializes `path` into `object` (a fresh one: on failure the caller's map is untouched)
/// after checking its checksum; throws std::runtime_error naming the file and `kind`.
void LoadInto(mrpt::serialization::CSerializable& object, const std::string& path,
              const std::string& kind);

/// Whether `path` is a plain map file of class `kind` ("CAppearanceMap"): MRPT's archive names
/// the class in its first bytes. False for anything else, a gzip'd file among them.
bool IsMapFileOf(const std::string& path, const std::string& kind);

/// What a file's trailer says of it.
enum class MapChecksum {
  kMatches,   ///< the trailer is there and matches the bytes before it
  kMissing,   ///< no trailer: an older or gzip'd file
  kMismatch,  ///< the trailer is there and the bytes changed
};
/// Reads `path` once; throws std::runtime_error naming it if it cannot be read.
MapChecksum CheckMapChecksum(const std::string& path);

}  // namespace novelty::mrpt_plugins
