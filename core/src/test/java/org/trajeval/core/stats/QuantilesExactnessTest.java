package org.trajeval.core.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/**
 * Every quantile and tail the statistics use, against 50-digit references.
 *
 * <p>Source of every reference value: mpmath 1.4.1 at {@code mp.dps = 50} (script
 * {@code quantiles.py}, run once by hand in a throwaway venv, never at test time), with the inputs
 * taken as the exact doubles Java passes (alpha = 1 - level, q = alpha/2 as doubles):
 * <ul>
 *   <li>Clopper-Pearson lower: {@code findroot(lambda x: betainc(f, n-f+1, 0, x, regularized=True) - q)},
 *       upper: {@code findroot(lambda x: betainc(n-f, f+1, 0, 1-x, regularized=True) - q)};</li>
 *   <li>t: {@code findroot(lambda t: betainc(df/2, 1/2, 0, df/(df+t*t), regularized=True)/2 - q)};</li>
 *   <li>normal quantile: {@code -sqrt(2)*erfinv(2*q-1)}; normal tail: {@code erfc(z/sqrt(2))/2}.</li>
 * </ul>
 */
class QuantilesExactnessTest {
    /** Issue 20: every quantile and tail to 1e-12 relative of a high-precision reference. */
    private static final double REL_TOL = 1e-12;

    private static final double[][] CLOPPER_PEARSON = {
        {0.95, 1.0, 40, 0.00063274493204941952804, 0.13158585848276572078},
        {0.95, 3, 40, 0.01574217985104153686, 0.20386474873289895594},
        {0.95, 0.0, 40, 0.0, 0.088097302878802370265},
        {0.95, 40, 40, 0.91190269712119762973, 1.0},
        {0.95, 39, 40, 0.86841414151723427922, 0.99936725506795058047},
        {0.95, 20, 40, 0.33801781373723461702, 0.66198218626276538298},
        {0.95, 1.0, 2, 0.012579117093425060372, 0.98742088290657493963},
        {0.95, 0.0, 1.0, 0.0, 0.9749999999999999778},
        {0.95, 1.0, 1.0, 0.025000000000000022204, 1.0},
        {0.95, 5, 200, 0.00816616619084251333, 0.057374351126845859457},
        {0.95, 2, 7, 0.036692566176085560404, 0.70957913626265723082},
        {0.99, 1.0, 40, 0.00012530569417421945178, 0.17151532886809393689},
        {0.99, 3, 40, 0.0086277888417227381631, 0.24837227476949525117},
        {0.99, 0.0, 40, 0.0, 0.12406021952937567559},
        {0.99, 40, 40, 0.87593978047062432441, 1.0},
        {0.99, 39, 40, 0.82848467113190606311, 0.99987469430582578055},
        {0.99, 20, 40, 0.2946133873497665844, 0.7053866126502334156},
        {0.99, 1.0, 2, 0.0025031328369998356433, 0.99749686716300016436},
        {0.99, 0.0, 1.0, 0.0, 0.99499999999999999556},
        {0.99, 1.0, 1.0, 0.0050000000000000044409, 1.0},
        {0.99, 5, 200, 0.0054294527982318159555, 0.069145638069679661592},
        {0.99, 2, 7, 0.015844329428770718748, 0.79702760429669798673},
        {0.9, 1.0, 40, 0.0012815105228752599424, 0.11318836094473756582},
        {0.9, 3, 40, 0.020753601475701202961, 0.18258685001590124996},
        {0.9, 0.0, 40, 0.0, 0.072157524505514575466},
        {0.9, 40, 40, 0.92784247549448542453, 1.0},
        {0.9, 39, 40, 0.88681163905526243418, 0.99871848947712474006},
        {0.9, 20, 40, 0.36109165999833782224, 0.63890834000166217776},
        {0.9, 1.0, 2, 0.025320565519103603621, 0.97467943448089639638},
        {0.9, 0.0, 1.0, 0.0, 0.9500000000000000111},
        {0.9, 1.0, 1.0, 0.049999999999999988898, 1.0},
        {0.9, 5, 200, 0.009901244217107582321, 0.051843339120290534632},
        {0.9, 2, 7, 0.053375500470237187195, 0.65873856384466405291},
    };
    private static final double[][] STUDENT_UPPER = {
        {0.025000000000000022, 1.0, 12.706204736174693314},
        {0.025000000000000022, 2, 4.3026527297494617894},
        {0.025000000000000022, 3, 3.1824463052837084359},
        {0.025000000000000022, 4, 2.7764451051977934898},
        {0.025000000000000022, 7, 2.3646242515927847379},
        {0.025000000000000022, 29, 2.0452296421327038745},
        {0.025000000000000022, 55, 2.0040447832891454965},
        {0.025000000000000022, 100, 1.9839715185235518946},
        {0.04999999999999999, 1.0, 6.3137515146750445242},
        {0.04999999999999999, 2, 2.9199855803537260661},
        {0.04999999999999999, 3, 2.3533634348018241223},
        {0.04999999999999999, 4, 2.1318467863266505158},
        {0.04999999999999999, 7, 1.8945786050900075405},
        {0.04999999999999999, 29, 1.6991270265334978672},
        {0.04999999999999999, 55, 1.6730339652899118136},
        {0.04999999999999999, 100, 1.6602343260853396657},
        {0.0050000000000000044, 1.0, 63.656741162871524447},
        {0.0050000000000000044, 2, 9.9248432009182886403},
        {0.0050000000000000044, 3, 5.8409093097333554113},
        {0.0050000000000000044, 4, 4.6040948713499920459},
        {0.0050000000000000044, 7, 3.4994832973504932609},
        {0.0050000000000000044, 29, 2.7563859036706051204},
        {0.0050000000000000044, 55, 2.6682159884861935777},
        {0.0050000000000000044, 100, 2.625890521438017607},
        {0.2, 1.0, 1.3763819204711734373},
        {0.2, 2, 1.0606601717798212253},
        {0.2, 3, 0.97847231236330438961},
        {0.2, 4, 0.9409645772351811203},
        {0.2, 7, 0.89602964431376490985},
        {0.2, 29, 0.85419198588185561464},
        {0.2, 55, 0.84820543265625677476},
        {0.2, 100, 0.84523042449101604133},
        {0.3, 1.0, 0.72654252800536093919},
        {0.3, 2, 0.61721339984836768183},
        {0.3, 3, 0.58438972743981870658},
        {0.3, 4, 0.56864906304970548011},
        {0.3, 7, 0.54910965794728504901},
        {0.3, 29, 0.53021439570916085142},
        {0.3, 55, 0.52745361453260148767},
        {0.3, 100, 0.52607627060034633238},
        {0.45, 1.0, 0.15838444032453625809},
        {0.45, 2, 0.14213381090374025765},
        {0.45, 3, 0.13659819935369887693},
        {0.45, 4, 0.13383036711194332601},
        {0.45, 7, 0.13029279659177735831},
        {0.45, 29, 0.1267666056202748147},
        {0.45, 55, 0.12624293321698295233},
        {0.45, 100, 0.12598088204153964654},
        {1e-08, 1.0, 31830988.618379056016},
        {1e-08, 2, 7071.0677057994575501},
        {1e-08, 3, 479.52506957973828093},
        {1e-08, 4, 131.59473694062355172},
        {1e-08, 7, 27.802283188119888963},
        {1e-08, 29, 7.6416831323814395532},
        {1e-08, 55, 6.5572071327990190513},
        {1e-08, 100, 6.1015734720297957686},
    };
    private static final double[][] NORMAL_UPPER = {
        {0.025000000000000022, 1.9599639845400538556},
        {0.04999999999999999, 1.6448536269514728225},
        {0.0050000000000000044, 2.5758293035489004539},
        {0.2, 0.84162123357291416552},
        {0.45, 0.12566134685507400616},
        {1e-10, 6.3613409024040561991},
        {1e-20, 9.2623400897984075796},
    };
    private static final double[][] NORMAL_TAIL = {
        {0.0, 0.5},
        {1.0, 0.15865525393145705141},
        {1.959963984540054, 0.025000000000000010876},
        {3.0, 0.0013498980316300945267},
        {6.21, 2.649230067999402959e-10},
        {8.5, 9.4795348222033183542e-18},
        {20.0, 2.7536241186062336951e-89},
        {37.0, 5.7255712225245768227e-300},
    };

    @Test
    void clopperPearsonBoundsAgreeWithFiftyDigitBetaInversesToTheLastDigits() {
        // the case: 1 failure in 40 at 95 %: lower 6.327449320e-4 (Commons Math's solver gave 6.327448330e-4)
        double worst = 0.0;
        for (double[] c : CLOPPER_PEARSON) {
            Interval ci = BinomialInterval.CLOPPER_PEARSON.of((int) c[1], (int) c[2], c[0]);
            worst = Math.max(worst, relErr(c[3], ci.lower()));
            worst = Math.max(worst, relErr(c[4], ci.upper()));
            assertRelative(c[3], ci.lower(), "lower " + c[1] + "/" + c[2] + " at " + c[0]);
            assertRelative(c[4], ci.upper(), "upper " + c[1] + "/" + c[2] + " at " + c[0]);
        }
        System.out.println("Clopper-Pearson max relative error " + worst);
    }

    @Test
    void studentQuantilesAgreeWithFiftyDigitReferences() {
        double worst = 0.0;
        for (double[] c : STUDENT_UPPER) {
            double t = Quantiles.studentUpper(c[0], (int) c[1]);
            worst = Math.max(worst, relErr(c[2], t));
            assertRelative(c[2], t, "t upper q = " + c[0] + ", df = " + c[1]);
        }
        System.out.println("t quantile max relative error " + worst);
    }

    @Test
    void normalQuantilesAgreeWithFiftyDigitReferencesDeepIntoTheTail() {
        double worst = 0.0;
        for (double[] c : NORMAL_UPPER) {
            double z = Quantiles.normalUpper(c[0]);
            worst = Math.max(worst, relErr(c[1], z));
            assertRelative(c[1], z, "normal upper q = " + c[0]);
            assertRelative(-c[1], Quantiles.normal(c[0]), "normal lower p = " + c[0]);
        }
        System.out.println("normal quantile max relative error " + worst);
    }

    @Test
    void normalUpperTailKeepsItsDigitsWhereOneMinusCdfWouldCancel() {
        // at z = 6.21 the old 2(1 - Phi(z)) gave 5.301097339e-10 for the two-sided p; exact 5.301097467e-10
        double worst = 0.0;
        for (double[] c : NORMAL_TAIL) {
            double q = Quantiles.normalUpperTail(c[0]);
            worst = Math.max(worst, relErr(c[1], q));
            assertRelative(c[1], q, "normal tail z = " + c[0]);
        }
        System.out.println("normal tail max relative error " + worst);
    }

    @Test
    void wilsonBoundsUseTheExactNormalQuantile() {
        // Wilson 95 %, f = 1, n = 40, written out with z = 1.9599639845400538556 (mpmath, above):
        // centre (p + z^2/2n)/(1 + z^2/n), half z sqrt(p(1-p)/n + z^2/4n^2)/(1 + z^2/n); evaluated by mpmath:
        // lower 0.0044268315026814028906, upper 0.12881368963474088882
        Interval w = BinomialInterval.WILSON.of(1, 40, 0.95);
        assertRelative(0.0044268315026814028906, w.lower(), "Wilson lower");
        assertRelative(0.12881368963474088882, w.upper(), "Wilson upper");
    }

    private static double relErr(double expected, double actual) {
        return expected == 0.0 ? Math.abs(actual) : Math.abs(actual - expected) / Math.abs(expected);
    }

    private static void assertRelative(double expected, double actual, String what) {
        assertEquals(expected, actual, REL_TOL * Math.abs(expected), what);
    }
}
