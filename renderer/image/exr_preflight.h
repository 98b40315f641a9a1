// What is refused about an OpenEXR file before OpenEXR reads it: a header attribute that claims more bytes
// than the file holds (OpenEXR allocates and clears an attribute's claimed size before reading it, so a few
// hundred bytes of file could make it take up to 2 GB before it finds the file short), and a channel of a
// pixel type other than UINT, HALF and FLOAT (OpenEXR passes it on, and OpenImageIO 2.4 aborts on it), or a
// channel list that does not end where its claimed size says (OpenEXR reads on past it), and chunks (blocks of
// scanlines or tiles) larger than any image glossy reads needs (OpenEXR allocates a chunk's buffers when it
// opens the file, from the header's data window alone).
#pragma once

#include <filesystem>

namespace glossy {

// Throws InputError naming the file and the attribute or channel when an OpenEXR file's headers do not fit
// in it, declare a channel of an unknown pixel type or chunks too large.
// Files that do not start with the OpenEXR magic number are left to their readers.
void preflightExr(const std::filesystem::path& path);

}  // namespace glossy
