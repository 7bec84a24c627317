#pragma once
// Internal to og_data: GRIB (edition 1 and 2) files read with ecCodes, as a GridFile.
// Messages are framed by this code (section 0 length, "7777" trailer, bounded by the file
// size) before ecCodes sees them, so a hostile length cannot make anyone allocate or read
// beyond the file. Only regular latitude/longitude grids ("regular_ll") are accepted.
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "data/GridFile.hpp"

namespace og::data::detail {

/// True when `head` (the first bytes of a file) starts a GRIB message.
bool looksLikeGrib(std::string_view head);

/// Opens a GRIB file; fields are named by ecCodes' shortName (e.g. "10u"), with
/// "@typeOfLevel=level" appended when a shortName occurs on several levels.
std::unique_ptr<GridFile> openGrib(const std::filesystem::path& file);
/// Same for an in-memory image (copied); `label` names it in messages.
std::unique_ptr<GridFile> openGribMemory(std::string_view bytes, const std::string& label);

}  // namespace og::data::detail
