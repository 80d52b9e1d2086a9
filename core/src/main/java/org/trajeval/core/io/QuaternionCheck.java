package org.trajeval.core.io;

import java.util.Locale;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/** Refuses a quaternion whose norm differs from 1 by more than the tolerance. */
final class QuaternionCheck {
    private QuaternionCheck() {
    }

    /** @return | |q| - 1 | */
    static double normError(double w, double x, double y, double z) {
        return Math.abs(Math.sqrt(w * w + x * x + y * y + z * z) - 1.0);
    }

    /**
     * @param columns the quaternion's column names in file order, e.g. "qx qy qz qw"
     * @param found the four fields as written
     */
    static InputException refuse(String source, long line, String columns, double w, double x, double y, double z,
            double tolerance, String found) {
        double norm = Math.sqrt(w * w + x * x + y * y + z * z);
        return new InputException(source, line, columns, InputProblem.NON_UNIT_QUATERNION,
                "the quaternion (" + columns + ") must have norm 1 within " + tolerance + ", its norm is "
                        + String.format(Locale.ROOT, "%.6g", norm),
                found);
    }
}
