package org.trajeval.figures;

import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import org.trajeval.core.report.EvaluationSeries;

/**
 * Box plots of the relative error per sub-trajectory length (rpg_trajectory_evaluation's
 * figure): one category per length, translation (%) and rotation (deg/m), one box per result
 * and length (results side by side within a length, coloured by result). Drawn by
 * {@code eval --plot} for one result and by {@code res --plot} for several.
 */
final class SubTrajectoryFigures {
    private SubTrajectoryFigures() {
    }

    /**
     * The segments of one result.
     *
     * @param name legend entry, or null for a single result
     * @param rgb colour of its boxes
     * @param segments its segments
     */
    record Named(String name, int rgb, EvaluationSeries.Segments segments) {
    }

    /** @return {@code subtraj_trans} and {@code subtraj_rot}, or nothing when no result has segments */
    static List<Figure> of(List<Named> given) {
        List<Named> results = given.stream().filter(r -> r.segments().size() > 0).toList();
        TreeSet<Double> all = new TreeSet<>();
        int segments = 0;
        for (Named r : results) {
            for (double l : r.segments().lengths()) {
                all.add(l);
            }
            segments += r.segments().size();
        }
        if (segments == 0) {
            return List.of();
        }
        List<Double> lengths = new ArrayList<>(all);
        List<String> names = lengths.stream().map(l -> EvalFigures.fmt(l) + " m").toList();
        String count = results.size() == 1 ? " (" + segments + " segments)" : "";
        return List.of(
                figure("subtraj_trans", "Relative translation error per sub-trajectory length" + count,
                        "translation error (%)", results, lengths, names, true),
                figure("subtraj_rot", "Relative rotation error per sub-trajectory length" + count,
                        "rotation error (deg/m)", results, lengths, names, false));
    }

    private static Figure figure(String name, String title, String label, List<Named> results, List<Double> lengths,
            List<String> categories, boolean translation) {
        int r = results.size();
        double spacing = 0.8 / r;
        List<Layer> layers = new ArrayList<>();
        List<double[]> values = new ArrayList<>();
        for (int ri = 0; ri < r; ri++) {
            Named n = results.get(ri);
            EvaluationSeries.Segments s = n.segments();
            double[] column = translation ? s.transPct() : s.rotDegPerM();
            List<Layer.Box> boxes = new ArrayList<>();
            List<Double> at = new ArrayList<>();
            for (int li = 0; li < lengths.size(); li++) {
                double[] v = s.at(column, lengths.get(li));
                if (v.length == 0) {
                    continue;
                }
                values.add(v);
                boxes.add(ResFigures.box(v, n.rgb()));
                at.add(li + 1 + (ri - (r - 1) / 2.0) * spacing);
            }
            if (!boxes.isEmpty()) {
                layers.add(new Layer.Boxes(n.name(), boxes, at.stream().mapToDouble(Double::doubleValue).toArray(),
                        0.4 * spacing));
            }
        }
        return new Figure(name, title, Axis.categorical("sub-trajectory length", categories),
                Axis.fromZero(label, values.toArray(new double[0][])), layers, null, false);
    }
}
