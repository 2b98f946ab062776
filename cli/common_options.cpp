#include "common_options.hpp"

#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "config/option_table.hpp"

namespace rbcsim::cli {
namespace {

// Help of an option that picks an overlay of share/ (--morphology, --preset): its choices from
// the option table.
std::string overlay_help(std::string_view path, std::string help) {
  const auto& option = *config::option_table().find(path);
  for (const auto& choice : option.choices) help.append(" ").append(choice);
  return help + " (default: " + option.default_value.get<std::string>() +
         "; overrides config files and --set)";
}

}  // namespace

std::string with_default(std::string help, std::string_view path) {
  const auto* option = config::option_table().find(path);
  if (option == nullptr) throw std::logic_error("help text names no option " + std::string(path));
  const auto& value = option->default_value;
  std::string shown;
  if (value.is_string()) {
    shown = value.get<std::string>();
  } else if (value.is_number()) {
    shown = format_number(value.get<double>());
  } else if (value.is_array()) {
    for (const auto& item : value) {
      shown +=
          (shown.empty() ? "" : ",") + (item.is_string() ? item.get<std::string>() : item.dump());
    }
  } else {
    shown = value.dump();
  }
  return help + " (default: " + shown + ")";
}

std::optional<long long> whole_number(const std::string& text) {
  std::size_t used = 0;
  long long value = 0;
  try {
    value = std::stoll(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (used != text.size()) return std::nullopt;
  return value;
}

CLI::Validator whole_number_at_least(long long minimum) {
  return CLI::Validator(
      [minimum](const std::string& text) {
        const auto value = whole_number(text);
        if (!value || *value < minimum) {
          return in_quotes(text) + " is not a whole number >= " + std::to_string(minimum);
        }
        return std::string();
      },
      "");
}

void add_config_options(CLI::App* command, config::ConfigRequest& request) {
  command
      ->add_option("--config", request.files,
                   "JSON config file; repeatable, later files override earlier ones")
      ->type_name("FILE")
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  command
      ->add_option("--set", request.assignments,
                   "Override one option, e.g. --set membrane.k_bend_kBT=60; repeatable, applied "
                   "after the config files")
      ->type_name("KEY.PATH=VALUE")
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  command
      ->add_option("--morphology", request.morphology,
                   overlay_help("morphology", "Cell morphology and its Table 2 parameters:"))
      ->type_name("NAME");
  command
      ->add_option("--preset", request.preset,
                   overlay_help("preset", "Whole parameter set, under the morphology's and yours:"))
      ->type_name("NAME");
}

void add_common_options(CLI::App* command, CommonOptions& options) {
  add_config_options(command, options.config);
  command->add_option("--output", options.output_directory, "Directory for the run's files")
      ->type_name("DIR");
  command->add_option("--threads", options.threads, "OpenMP threads (default: all cores)")
      ->type_name("N")
      ->check(whole_number_at_least(1));
  command->add_flag("--json", options.json, "Print the machine-readable result on stdout");
  auto* quiet = command->add_flag("--quiet", options.quiet, "Print only errors");
  command
      ->add_flag("--verbose", options.verbose,
                 "Print more detail; progress lines on stderr also when it is not a terminal")
      ->excludes(quiet);
}

void assign_option(config::ConfigRequest& request, std::string_view option, std::string_view path,
                   const std::string& value) {
  request.option_assignments.push_back({std::string(option), std::string(path) + "=" + value});
}

CheckpointInterval parse_checkpoint_interval(std::string_view text) {
  const auto fail = [&text]() -> CheckpointInterval {
    throw InputError("--checkpoint-every", "\"" + std::string(text) +
                                               "\": expected a number of steps (5000) or a "
                                               "wall-clock time with s, m or h (90s, 10m, 2h)");
  };
  const std::string number(text.substr(0, text.find_first_not_of("0123456789.")));
  const auto unit = text.substr(number.size());
  if (number.empty() || number.find('.') != number.rfind('.')) return fail();
  const double value = std::stod(number);
  if (!(value > 0.0)) return fail();
  if (unit.empty()) {
    if (number.find('.') != std::string::npos) return fail();  // steps are whole
    return {static_cast<std::size_t>(std::stoull(number)), 0.0};
  }
  for (const auto& [suffix, seconds] : {std::pair{"s", 1.0}, {"m", 60.0}, {"h", 3600.0}}) {
    if (unit == suffix) return {0, value * seconds};
  }
  return fail();
}

void add_checkpoint_options(CLI::App* command, CheckpointOptions& options, CommonOptions& common) {
  command
      ->add_option("--checkpoint-every", options.every,
                   "Write <run dir>/checkpoint.bin every N steps (5000) or wall-clock time (90s, "
                   "10m, 2h); a checkpoint is also written when interrupted (Ctrl-C)")
      ->type_name("N|TIME")
      ->check([](const std::string& text) {
        try {
          parse_checkpoint_interval(text);
          return std::string();
        } catch (const InputError& error) {
          return std::string(error.what());
        }
      });
  command
      ->add_option("--resume", options.resume_directory,
                   "Continue the run in DIR from its checkpoint.bin (same config and options)")
      ->type_name("DIR")
      ->each([&common](const std::string& directory) {
        common.output_directory = directory;
        common.resuming = true;
      })
      ->excludes(command->get_option("--output"));
}

config::Config resolve_config(const CommonOptions& options) {
  return config::resolve_config(options.config);
}

void print_notices(std::span<const std::string> notices) {
  for (const auto& notice : notices) std::cerr << "rbcsim: notice: " << notice << '\n';
}

}  // namespace rbcsim::cli
