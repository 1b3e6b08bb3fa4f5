#pragma once
// Recorded panoramas: the paper's real-robot use.  A recording is a folder of 128x512 RGB panoramas (PNG or
// JPEG) and a poses.csv naming each image and the pose it was taken at, in the order taken:
//
//   image,x,y,yaw
//   pano_00000.png,-91.3,-49.7,0.0
//
// (x, y in world units, yaw in radians counter-clockwise from +x).  Column j of a panorama looks along bearing
// -pi + 2*pi*j/512 counter-clockwise from the heading (core::ColumnToBearing): the centre column looks straight
// ahead and the columns right of it look to the robot's LEFT, so a camera whose panorama turns clockwise from
// left to right must be flipped horizontally first.  Row 0 is the top; the horizon is the middle row.  `toponav render
// --sequence DIR` writes one from a simulated world; `toponav map --images DIR` builds the map from one with an image
// detector behind the sensor factory (`sensor: {kind: recorded}`).
#include <memory>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/observation.h"
#include "mapping/mapping.h"

namespace toponav::experiments {

struct RecordedFrame {
  std::string image;  // path (as given in poses.csv, relative to the recording folder)
  core::Pose2 pose;
};

struct Recording {
  std::string dir;                    // the folder the image paths are relative to
  std::vector<RecordedFrame> frames;  // in the order taken
  std::string ImagePath(size_t i) const;
};

// Reads 'poses_csv' (default: DIR/poses.csv).  Throws core::DataError naming the file and line for a missing
// file, a bad header, a malformed or non-finite number, or an empty recording.
Recording ReadRecording(const std::string& dir, const std::string& poses_csv = "");

// Writes the panoramas as DIR/pano_NNNNN.png and DIR/poses.csv.
void WriteRecording(const std::string& dir, const std::vector<core::Pose2>& poses,
                    const std::vector<core::Panorama>& panoramas);

// An 8-bit colour image file as an RGB panorama (alpha dropped, grey expanded).  Throws core::DataError naming
// the file if it cannot be read.
core::Panorama ReadPanorama(const std::string& path);

// A pose-in sensor that replays a recording: Observe(pose) runs the detector on the frame taken at 'pose'
// (the next frame in order whose pose equals it within 1e-6; a pose the recording does not hold is a
// core::DataError).
std::unique_ptr<core::VertexSensorInterface> CreateRecordedSensor(
    Recording recording, std::unique_ptr<core::VertexDetectorInterface> detector);

struct RecordedMapOptions {
  // MCMC every this many frames (and once at the end); 0: never (every vertex with enough detections kept).
  int mcmc_every = 5;
  uint64_t seed = 0;   // MCMC randomness
};

struct RecordedMapResult {
  mapping::MapView view;    // the final map, known space rebuilt exactly
  std::vector<core::Vec2> path;
  int frames = 0;
  double log_posterior = 0.0;
  double mean_observe_ms = 0.0;  // reading the image and running the detector, per frame
  double mean_update_ms = 0.0;   // the map update (and MCMC), per frame
};

// Builds the map from every frame of 'recording' in order, observing through 'sensor' (closed world: no
// open region; no world bounds).
RecordedMapResult BuildRecordedMap(const Recording& recording, core::VertexSensorInterface& sensor,
                                   const mapping::MapperOptions& mapping, const RecordedMapOptions& options);

}  // namespace toponav::experiments
