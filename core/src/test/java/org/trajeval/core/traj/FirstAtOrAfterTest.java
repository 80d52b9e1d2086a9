package org.trajeval.core.traj;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The binary search over stamps finds the first pose at or after a time, within a range. */
class FirstAtOrAfterTest {
    // stamps 0, 1, 1, 1, 2, 5 (s): a kept duplicate run in the middle
    private final Trajectory t = PlanarTrajectory.of(new double[] {0, 1, 1, 1, 2, 5}, new double[6], new double[6],
            new double[6]);

    @Test
    void findsTheFirstOfEqualStampsAndTheNextLaterOne() {
        assertEquals(0, t.firstAtOrAfter(-3, 0, 6));
        assertEquals(0, t.firstAtOrAfter(0, 0, 6));
        assertEquals(1, t.firstAtOrAfter(0.5, 0, 6));
        assertEquals(1, t.firstAtOrAfter(1, 0, 6));
        assertEquals(4, t.firstAtOrAfter(1.5, 0, 6));
        assertEquals(5, t.firstAtOrAfter(5, 0, 6));
    }

    @Test
    void answersTheRangeEndWhenNoPoseOfTheRangeQualifies() {
        assertEquals(6, t.firstAtOrAfter(7, 0, 6));
        assertEquals(4, t.firstAtOrAfter(3, 1, 4)); // stamps 1, 1, 1 only
        assertEquals(2, t.firstAtOrAfter(0, 2, 5)); // the range starts later
    }
}
