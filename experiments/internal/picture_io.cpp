#include "experiments/internal/picture_io.h"

#include <opencv2/imgcodecs.hpp>

#include "core/error.h"

namespace toponav::experiments::internal {

void SavePicture(const cv::Mat& image, const std::string& path) {
  bool ok = false;
  try {
    ok = cv::imwrite(path, image);
  } catch (const cv::Exception& e) {
    throw core::DataError(path, std::string("cannot write the picture: ") + e.what());
  }
  if (!ok) throw core::DataError(path, "cannot write the picture");
}

}  // namespace toponav::experiments::internal
