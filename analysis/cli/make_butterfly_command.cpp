// `oflab-cli make-butterfly`: writes the bundled demo texture (analysis/generators/butterfly.h).
#include <ostream>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "formats/image_io.h"
#include "generators/butterfly.h"

namespace oflab {

int run_make_butterfly_command(const CommandArgs& args, std::ostream& out, std::ostream& err) {
  try {
    const CliArgs a(args, {{"--out", 1}, {"--force", 0}});
    const std::string path = a.values("--out").at(0);
    const Overwrite overwrite = check_out_file("--out", path, a.has("--force"));
    write_png(path, make_butterfly(), overwrite);
    out << "wrote " << path << " (243 x 198 RGBA)\n";
    return 0;
  } catch (const FileWriteError& e) {
    err << "oflab-cli make-butterfly: --out: " << e.what() << "\n";
    return 1;
  } catch (const ImageFileError& e) {
    err << "oflab-cli make-butterfly: --out: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace oflab
