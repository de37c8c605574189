// STL is parsed by aokit itself (io/StlFormat.h); the check is a full parse whose mesh is dropped,
// so that its errors come before any reader process starts, like every other format's.

#include "io/PrecheckText.h"
#include "io/StlFormat.h"

namespace aokit {

void precheckStl(std::string_view data) { parseStl(data); }

}  // namespace aokit
