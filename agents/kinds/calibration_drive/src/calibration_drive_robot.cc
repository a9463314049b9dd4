#include "dream/calibration_drive/calibration_drive_robot.h"

#include "dream/calibration_drive/calibration_drive.h"

namespace dream::calibration_drive {

agents::UnicycleCommand CalibrationDriveRobot::Update(int64_t step) {
  // The command of the program's last step is its last: the world applies it
  // and then, every robot done, ends the run at CalibrationDrive::Steps().
  done_ = step >= CalibrationDrive::Steps() - 1;
  return CalibrationDrive::CommandAt(step);
}

}  // namespace dream::calibration_drive
