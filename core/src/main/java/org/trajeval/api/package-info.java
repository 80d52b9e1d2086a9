/**
 * The public Java API of trajeval: {@link org.trajeval.api.TrajectoryEvaluator} (two files, or two
 * trajectories as {@link org.trajeval.api.Poses} arrays, plus settings, in; the report out).
 *
 * <p><b>What is public</b> (covered by semantic versioning: within one major version no public
 * type or member below is removed or changes meaning; a new minor version may add to them; the
 * JSON report keeps its {@code schema_version} until an incompatible change):
 * <ul>
 *   <li>{@code org.trajeval.api}: this package;</li>
 *   <li>{@code org.trajeval.core}: {@code Version}, {@code InputException}, {@code InputProblem};</li>
 *   <li>{@code org.trajeval.core.report}: {@code EvaluationReport} (with its nested records) and
 *       {@code ReportJson};</li>
 *   <li>the settings' keys and values (the table of {@code org.trajeval.core.options.Setting},
 *       shared with {@code trajeval eval}, suite manifests and {@code run.yaml}): a key is not
 *       removed and keeps its meaning within a major version.</li>
 * </ul>
 * Everything else in the published artefacts ({@code trajeval-core}, {@code trajeval-cli},
 * {@code trajeval-pipeline}, ...) is internal: public only so that trajeval's own modules can use
 * it, and free to change in any release.
 */
package org.trajeval.api;
