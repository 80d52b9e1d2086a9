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
 *   <li>{@code org.trajeval.core.eval}: {@code EvaluationOptions}, {@code Convention},
 *       {@code PlanarProjection};</li>
 *   <li>the option types those use: {@code org.trajeval.core.align.AlignmentModel},
 *       {@code org.trajeval.core.assoc.AssociationMethod}, {@code org.trajeval.core.assoc.OverlapPolicy},
 *       {@code org.trajeval.core.metric.DriftOptions}, {@code PairSelection}, {@code PairsFrom},
 *       {@code RpeUnit}.</li>
 * </ul>
 * Everything else in the published artefacts ({@code trajeval-core}, {@code trajeval-cli},
 * {@code trajeval-pipeline}, ...) is internal: public only so that trajeval's own modules can use
 * it, and free to change in any release.
 */
package org.trajeval.api;
