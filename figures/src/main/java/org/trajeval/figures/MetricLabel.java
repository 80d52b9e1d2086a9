package org.trajeval.figures;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * A human label with unit for a metric key ({@code ate_rot_rmse_rad} -> "ATE rotation RMSE (deg)"),
 * read from the key's words and its unit suffix; angles are shown in degrees.
 *
 * @param label label with unit
 * @param factor multiplies a value in the key's unit to the label's unit (180/pi for rad)
 */
public record MetricLabel(String label, double factor) {
    private static final Map<String, String> WORDS = Map.of("ate", "ATE", "rpe", "RPE", "trans", "translation",
            "rot", "rotation", "rmse", "RMSE", "score", "score S");

    /** @return the label of a key; unknown words are kept as they are */
    public static MetricLabel of(String key) {
        String[] w = key.split("_");
        String unit = w.length > 1 ? w[w.length - 1] : "";
        String shown;
        double f = 1.0;
        int words = w.length - 1;
        switch (unit) {
            case "m" -> shown = "m";
            case "rad" -> {
                shown = "deg";
                f = 180.0 / Math.PI;
            }
            case "pct" -> shown = "%";
            case "s" -> shown = "s";
            default -> {
                shown = null;
                words = w.length;
            }
        }
        List<String> out = new ArrayList<>();
        for (int i = 0; i < words; i++) {
            out.add(WORDS.getOrDefault(w[i], w[i]));
        }
        return new MetricLabel(String.join(" ", out) + (shown == null ? "" : " (" + shown + ")"), f);
    }
}
