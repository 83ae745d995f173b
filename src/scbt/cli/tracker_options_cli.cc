// The tracker options of every command that tracks, made from the option table
// (scbt/tracker/option_table.h): one flag per user option, plus --config FILE.
#include <iostream>
#include <map>

#include "scbt/cli/commands.h"
#include "scbt/tracker/option_table.h"

namespace scbt::cli {

bool TrackerOptionFlags::apply(TrackerOptions* options) const {
  if (!config.empty()) read_tracker_options_file(config, options);
  for (const OptionSpec& spec : tracker_option_table()) {
    const auto given = flags.find(spec.name);
    if (given == flags.end() || given->second.option->count() == 0) continue;
    set_tracker_option(options, spec.name, given->second.text);
  }
  options->check();
  if (print_config) std::cout << tracker_options_text(*options) << std::flush;
  return print_config;
}

std::shared_ptr<TrackerOptionFlags> add_tracker_options(CLI::App* command) {
  auto flags = std::make_shared<TrackerOptionFlags>();
  const TrackerOptions defaults;
  command
      ->add_option("--config", flags->config,
                   "Tracker options from a YAML or JSON file: option names as in Python and ROS "
                   "(shape_weight: 2.0); flags given as well override it")
      ->group("Tracker options");
  command
      ->add_flag("--print-config", flags->print_config,
                 "Print the tracker options (defaults, --config, flags) as a config file and exit")
      ->group("Tracker options");
  for (const OptionSpec& spec : tracker_option_table()) {
    TrackerOptionFlags::Flag& flag = flags->flags[spec.name];
    std::string help = spec.help;
    if (spec.type == OptionType::kInt || spec.type == OptionType::kDouble) {
      help += "; range " + spec.range_text();
    }
    flag.option = command->add_option(spec.flag(), flag.text, help)
                      ->default_str(format_option_value(spec.get(defaults)))
                      ->type_name(spec.type == OptionType::kBool ? "true|false"
                                                                 : "<" + spec.type_name() + ">")
                      ->group("Tracker options: " + spec.group);
  }
  return flags;
}

}  // namespace scbt::cli
