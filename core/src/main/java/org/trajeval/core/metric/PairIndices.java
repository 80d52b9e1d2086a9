package org.trajeval.core.metric;

import java.util.Arrays;
import org.trajeval.core.traj.PoseSequence;

/**
 * Index pairs (i, j) for RPE. All rules are linear or n log n in the number of poses.
 * <ul>
 * <li>seconds, all pairs (the lesson): for every i, j = first index with t_j >= t_i + delta;
 * consecutive: the same rule chained from i = 0 (j becomes the next i), pairs do not overlap;
 * <li>frames (evo): consecutive (0, d), (d, 2d), ...; all pairs (i, i + d);
 * <li>metres (evo): consecutive: walk the path, a new index whenever the distance travelled since
 * the last one reaches delta; all pairs: for every i the j > i whose path distance from i is
 * closest to delta (the first on ties), kept if within 10 % of delta.
 * </ul>
 */
final class PairIndices {
    private final int[] first;
    private final int[] second;
    private final int count;

    private PairIndices(int[] first, int[] second, int count) {
        this.first = first;
        this.second = second;
        this.count = count;
    }

    int count() {
        return count;
    }

    int i(int k) {
        return first[k];
    }

    int j(int k) {
        return second[k];
    }

    static PairIndices compute(PoseSequence poses, double[] stamps, double delta, RpeUnit unit,
            PairSelection selection) {
        return switch (unit) {
            case SECONDS -> bySeconds(stamps, delta, selection);
            case FRAMES -> byFrames(poses.size(), (int) delta, selection);
            case METRES -> selection == PairSelection.ALL_PAIRS ? byPathAllPairs(poses, delta, 0.1 * delta)
                    : byPathConsecutive(poses, delta);
        };
    }

    private static PairIndices bySeconds(double[] t, double delta, PairSelection selection) {
        int n = t.length;
        int[] a = new int[n];
        int[] b = new int[n];
        int count = 0;
        if (selection == PairSelection.ALL_PAIRS) {
            int j = 0;
            for (int i = 0; i < n; i++) {
                double target = t[i] + delta;
                if (j < i) {
                    j = i;
                }
                while (j < n && t[j] < target) {
                    j++;
                }
                if (j >= n) {
                    break;
                }
                a[count] = i;
                b[count++] = j;
            }
        } else {
            int i = 0;
            int j = 0;
            while (true) {
                double target = t[i] + delta;
                while (j < n && t[j] < target) {
                    j++;
                }
                if (j >= n || j == i) {
                    break;
                }
                a[count] = i;
                b[count++] = j;
                i = j;
            }
        }
        return new PairIndices(a, b, count);
    }

    private static PairIndices byFrames(int n, int d, PairSelection selection) {
        int max = Math.max(0, n);
        int[] a = new int[max];
        int[] b = new int[max];
        int count = 0;
        if (selection == PairSelection.ALL_PAIRS) {
            for (int i = 0; i + d < n; i++) {
                a[count] = i;
                b[count++] = i + d;
            }
        } else {
            for (int i = 0; i + d < n; i += d) {
                a[count] = i;
                b[count++] = i + d;
            }
        }
        return new PairIndices(a, b, count);
    }

    /** Cumulative path length d_k = sum_{m<k} |p_{m+1} - p_m| (m). */
    static double[] accumulatedDistances(PoseSequence poses) {
        int n = poses.size();
        double[] d = new double[n];
        for (int k = 1; k < n; k++) {
            double dx = poses.x(k - 1) - poses.x(k);
            double dy = poses.y(k - 1) - poses.y(k);
            double dz = poses.z(k - 1) - poses.z(k);
            d[k] = d[k - 1] + Math.sqrt(dx * dx + dy * dy + dz * dz);
        }
        return d;
    }

    private static PairIndices byPathConsecutive(PoseSequence poses, double delta) {
        int n = poses.size();
        int[] ids = new int[Math.max(1, n)];
        int m = 0;
        if (n > 0) {
            ids[m++] = 0;
        }
        double path = 0.0;
        for (int k = 1; k < n; k++) {
            double dx = poses.x(k) - poses.x(k - 1);
            double dy = poses.y(k) - poses.y(k - 1);
            double dz = poses.z(k) - poses.z(k - 1);
            path += Math.sqrt(dx * dx + dy * dy + dz * dz);
            if (path >= delta) {
                ids[m++] = k;
                path = 0.0;
            }
        }
        int count = Math.max(0, m - 1);
        int[] a = new int[count];
        int[] b = new int[count];
        for (int k = 0; k < count; k++) {
            a[k] = ids[k];
            b[k] = ids[k + 1];
        }
        return new PairIndices(a, b, count);
    }

    /**
     * For every i: among k > i, the k minimising |(d_k - d_i) - delta|, the first such k on ties;
     * kept when that minimum is <= tol. The offsets d_k - d_i do not decrease in k, so the
     * minimiser is next to the first k whose offset reaches delta: found by a pointer that only
     * moves forward (linear time overall).
     */
    private static PairIndices byPathAllPairs(PoseSequence poses, double delta, double tol) {
        double[] d = accumulatedDistances(poses);
        int n = d.length;
        int[] a = new int[Math.max(0, n)];
        int[] b = new int[Math.max(0, n)];
        int count = 0;
        int k = 1;
        for (int i = 0; i < n - 1; i++) {
            if (k <= i) {
                k = i + 1;
            }
            // first k > i with (d_k - d_i) >= delta (or n)
            while (k < n && (d[k] - d[i]) < delta) {
                k++;
            }
            int best;
            double bestErr;
            if (k < n) {
                best = k;
                bestErr = Math.abs((d[k] - d[i]) - delta);
            } else {
                best = -1;
                bestErr = Double.POSITIVE_INFINITY;
            }
            if (k - 1 > i) {
                double below = Math.abs((d[k - 1] - d[i]) - delta);
                if (below <= bestErr) {
                    best = k - 1;
                    bestErr = below;
                }
            }
            if (best < 0) {
                continue;
            }
            // the first index with the same offset value (plateaus where the robot stands still)
            double value = d[best] - d[i];
            int lo = i + 1;
            int hi = best;
            while (lo < hi) {
                int mid = (lo + hi) >>> 1;
                if ((d[mid] - d[i]) < value) {
                    lo = mid + 1;
                } else {
                    hi = mid;
                }
            }
            best = lo;
            if (bestErr > tol) {
                continue;
            }
            a[count] = i;
            b[count++] = best;
        }
        return new PairIndices(Arrays.copyOf(a, count), Arrays.copyOf(b, count), count);
    }
}
