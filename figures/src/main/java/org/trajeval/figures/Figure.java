package org.trajeval.figures;

import java.util.List;
import java.util.Objects;

/**
 * A figure as data: title, axes (labels with units, ranges), layers, an optional colour scale
 * and whether both axes share one scale (paths in a plane). Renderers ({@link FigureFiles})
 * turn it into SVG and PNG; tests check this record, not pixels.
 *
 * @param name file stem, e.g. {@code "trajectories"}
 * @param title title (says what was done, e.g. the alignment actually applied)
 * @param x horizontal axis
 * @param y vertical axis
 * @param layers what is drawn, bottom first
 * @param colour colour scale of the {@link Layer.Gradient} layers, or null
 * @param equalScales true when one metre must be as long on both axes
 */
public record Figure(String name, String title, Axis x, Axis y, List<Layer> layers, ColourScale colour,
        boolean equalScales) {

    /** @throws IllegalArgumentException on a name that is not a plain file stem */
    public Figure {
        Objects.requireNonNull(title, "title");
        Objects.requireNonNull(x, "x");
        Objects.requireNonNull(y, "y");
        layers = List.copyOf(layers);
        if (!name.matches("[a-z0-9_\\-]+")) {
            throw new IllegalArgumentException("figure name must be [a-z0-9_-]+, found \"" + name + "\"");
        }
    }

    /** @return the layers of one kind */
    public <T extends Layer> List<T> layers(Class<T> kind) {
        return layers.stream().filter(kind::isInstance).map(kind::cast).toList();
    }
}
