#include "core/image_io.h"

#include <string>

#include "core/budgets.h"
#include "core/error.h"
#include "core/io/file_io.h"

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace bz {

void write_png(const std::filesystem::path& path, const Image& image) {
    std::string bytes;
    auto sink = [](void* ctx, void* data, int size) {
        static_cast<std::string*>(ctx)->append(static_cast<const char*>(data),
                                               static_cast<std::size_t>(size));
    };
    if (!stbi_write_png_to_func(sink, &bytes, image.width, image.height, image.channels,
                                image.pixels.data(), image.width * image.channels)) {
        throw UserError(path.string() + ": cannot encode PNG");
    }
    write_file_atomic(path, bytes);
}

Image read_png(const std::filesystem::path& path, int channels) {
    const std::string bytes = read_file(path, budget::kPngBytes);
    Image img;
    int comp = 0;
    unsigned char* data = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                                                static_cast<int>(bytes.size()), &img.width,
                                                &img.height, &comp, channels);
    if (!data) throw UserError(path.string() + ": not a readable PNG: " + stbi_failure_reason());
    img.channels = channels;
    img.pixels.assign(data, data + static_cast<std::size_t>(img.width) * img.height * channels);
    stbi_image_free(data);
    return img;
}

}  // namespace bz
