/**
 * ATE, RPE and drift. Internal: may change in any release; the public API is {@link org.trajeval.api}.
 */
package org.trajeval.core.metric;
