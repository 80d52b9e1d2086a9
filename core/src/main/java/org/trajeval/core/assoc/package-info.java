/**
 * Time association of two trajectories. Internal, except the option types
 * {@link org.trajeval.core.assoc.AssociationMethod} and {@link org.trajeval.core.assoc.OverlapPolicy}
 * (public API, see {@link org.trajeval.api}).
 */
package org.trajeval.core.assoc;
