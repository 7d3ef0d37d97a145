#pragma once
// The levels the title menu offers, shown as levels: each file's own name and one-line
// description (its `name` and `description` keys), the shipped ones first, then the player's
// own folder; within each, by the `menu_order` key, then by name. A level with
// `listed = false` (a benchmark scene) is left out; it still loads by path. A file that does
// not load is still listed, by its file name, so that choosing it shows what is wrong.
#include <filesystem>
#include <vector>

#include "app/play/menu/play_menus.h"

namespace bz::app::menu {

std::vector<LevelChoice> find_levels(const std::filesystem::path& shipped,
                                     const std::filesystem::path& user);

}  // namespace bz::app::menu
