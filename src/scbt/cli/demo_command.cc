#include "scbt/cli/commands.h"

namespace scbt::cli {

void add_demo_command(CLI::App& app, int* exit_code) {
  CLI::App* command = app.add_subcommand("demo", "Track a built-in synthetic clip (placeholder)");
  command->callback([exit_code] { *exit_code = 0; });
}

}  // namespace scbt::cli
