package org.trajeval.core.io;

import java.util.Locale;

/** File formats trajeval reads. */
public enum TrajectoryFormat {
    /** CSV with a header row; planar t,x,y,yaw by default (column names, delimiter, time unit configurable). */
    CSV,
    /** TUM RGB-D: {@code t tx ty tz qx qy qz qw} per line, space separated, seconds, w last; {@code #} comments. */
    TUM,
    /** KITTI odometry: 12 numbers per line (3x4 pose matrix, row-major), no stamps; optional times file. */
    KITTI,
    /** EuRoC ground-truth CSV: {@code t[ns], p_x, p_y, p_z, q_w, q_x, q_y, q_z, ...}, w first. */
    EUROC,
    /** NCLT ground truth or odometry CSV: {@code utime,x,y,z,roll,pitch,yaw}, no header, us, NED-like frame. */
    NCLT,
    /** Oxford RobotCar INS CSV ({@code gps/ins.csv}): northing, easting, down (m, NED) and roll, pitch, yaw, us. */
    ROBOTCAR_INS,
    /** Oxford RobotCar visual odometry ({@code vo/vo.csv}): relative poses, chained as the SDK chains them. */
    ROBOTCAR_VO,
    /** ICL-NUIM TUM-compatible ground truth ({@code *.gt.freiburg}): TUM columns whose first one is the frame index. */
    ICL_NUIM,
    /** A ROS bag (MCAP, ROS 1 bag, rosbag2 sqlite3 file or folder): one topic or TF trajectory of it. */
    BAG;

    /** @return the lower-case name used on the command line and in reports */
    public String id() {
        return name().toLowerCase(Locale.ROOT).replace('_', '-');
    }
}
