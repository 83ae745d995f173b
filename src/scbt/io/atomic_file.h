// The former name of OutputFile, kept while its callers move over.
#pragma once

#include "scbt/io/output_file.h"

namespace scbt {

using AtomicFile = OutputFile;

}  // namespace scbt
