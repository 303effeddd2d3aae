// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "setting_flags.h"

#include <string>
#include <type_traits>

namespace isovdb::cli {

void addSettingFlags(CLI::App& command, const std::vector<pipeline::Setting>& settings) {
  for (const pipeline::Setting& setting : settings) {
    const std::string flag = "--" + std::string(setting.name);
    const std::string help(setting.help);
    std::visit(
        [&](auto* value) {
          using T = std::remove_pointer_t<decltype(value)>;
          if constexpr (std::is_same_v<T, bool>) {
            // A setting on by default also takes --no-name, which turns it off.
            const std::string names = setting.negatable ? flag + ",!--no-" + std::string(setting.name) : flag;
            command.add_flag(names, *value, help)->default_str(*value ? "on" : "off");
          } else if constexpr (std::is_same_v<T, std::optional<float>>) {
            command.add_option(flag, *value, help);  // unset by default: no default shown
          } else {
            command.add_option(flag, *value, help)->capture_default_str();
          }
        },
        setting.value);
  }
}

}  // namespace isovdb::cli
