#pragma once
// Writing a picture (OpenCV): the one place that turns OpenCV's failures into core::DataError naming the file.
#include <opencv2/core.hpp>
#include <string>

namespace toponav::experiments::internal {

void SavePicture(const cv::Mat& image, const std::string& path);

}  // namespace toponav::experiments::internal
