// The help texts: what the program is, and two examples per subcommand.
#pragma once

namespace CLI {
class App;
}

namespace ogive::cli {

// The program's footer, and each registered subcommand's examples.
void add_help_texts(CLI::App& app);

}  // namespace ogive::cli
