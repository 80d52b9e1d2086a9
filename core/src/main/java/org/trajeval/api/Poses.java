package org.trajeval.api;

import java.util.Objects;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.SpatialTrajectory;
import org.trajeval.core.traj.Trajectory;

/**
 * A trajectory given as arrays, for {@link TrajectoryEvaluator#evaluate(Poses, Poses)}: one
 * entry per pose, timestamps strictly increasing. Planar poses are (t, x, y, yaw); spatial poses
 * are (t, x, y, z) with a unit quaternion (w, x, y, z; Hamilton, body to world), as in the TUM
 * format with w moved first. Worked example: yaw = +pi/2 rad, or q = (cos 45 deg, 0, 0, sin 45
 * deg), turns the body x axis onto world +y.
 *
 * <p>Immutable: the factories copy the arrays, so the caller may reuse them afterwards.
 */
public final class Poses {
    private final String name;
    private final Trajectory trajectory;

    private Poses(String name, Trajectory trajectory) {
        this.name = name;
        this.trajectory = trajectory;
    }

    /**
     * Planar poses.
     *
     * @param name what the report calls this trajectory (its {@code inputs.*.path})
     * @param t timestamps (s), strictly increasing
     * @param x positions (m)
     * @param y positions (m)
     * @param yaw headings (rad), counter-clockwise from +x
     * @throws IllegalArgumentException on arrays of different lengths, a non-finite value or
     *     timestamps that do not increase
     */
    public static Poses planar(String name, double[] t, double[] x, double[] y, double[] yaw) {
        return new Poses(requireName(name), PlanarTrajectory.of(t.clone(), x.clone(), y.clone(), yaw.clone()));
    }

    /**
     * Spatial (SE(3)) poses.
     *
     * @param name what the report calls this trajectory (its {@code inputs.*.path})
     * @param t timestamps (s), strictly increasing
     * @param x positions (m)
     * @param y positions (m)
     * @param z positions (m)
     * @param qw quaternion scalar part
     * @param qx quaternion vector part, x
     * @param qy quaternion vector part, y
     * @param qz quaternion vector part, z
     * @throws IllegalArgumentException on arrays of different lengths, a non-finite value, a zero
     *     quaternion or timestamps that do not increase
     */
    public static Poses spatial(String name, double[] t, double[] x, double[] y, double[] z, double[] qw,
            double[] qx, double[] qy, double[] qz) {
        return new Poses(requireName(name), SpatialTrajectory.of(t.clone(), x.clone(), y.clone(), z.clone(),
                qw.clone(), qx.clone(), qy.clone(), qz.clone()));
    }

    /** @return the name given to the factory */
    public String name() {
        return name;
    }

    /** @return the number of poses */
    public int size() {
        return trajectory.size();
    }

    /** @return true for planar poses (t, x, y, yaw) */
    public boolean isPlanar() {
        return trajectory instanceof PlanarTrajectory;
    }

    Trajectory trajectory() {
        return trajectory;
    }

    private static String requireName(String name) {
        Objects.requireNonNull(name, "name");
        if (name.isBlank()) {
            throw new IllegalArgumentException("a trajectory needs a name for its report, found an empty one");
        }
        return name;
    }
}
