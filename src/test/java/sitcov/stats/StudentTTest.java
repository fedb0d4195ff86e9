package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class StudentTTest {
    @Test
    void oneAndTwoDegreesOfFreedomHaveClosedForms() {
        // df = 1 is the Cauchy distribution, F(t) = 1/2 + atan(t)/pi; df = 2: F(t) = 1/2 + t / (2 sqrt(2 + t^2))
        for (double t : new double[] {-30, -3, -0.7, 0, 0.2, 1, 4.5, 100}) {
            assertEquals(0.5 + Math.atan(t) / Math.PI, StudentT.cdf(t, 1), 1e-13, "t=" + t);
            assertEquals(0.5 + t / (2 * Math.sqrt(2 + t * t)), StudentT.cdf(t, 2), 1e-13, "t=" + t);
        }
        assertEquals(Math.tan(0.475 * Math.PI), StudentT.quantile(0.975, 1), 1e-9);
    }

    @Test
    void thePairedTTestOfRsSleepExampleHasItsPublishedPValue() {
        // R's ?t.test: t.test(extra ~ group, data = sleep, paired = TRUE) gives t = -4.0621, df = 9,
        // p-value = 0.002833, 95 percent CI -2.4598858 -0.7001142 (Student 1908, Cushny & Peebles' data)
        double[] d = {-1.2, -2.4, -1.3, -1.3, 0.0, -1.0, -1.8, -0.8, -4.6, -1.4};
        double mean = Descriptive.mean(d);
        double se = Math.sqrt(Descriptive.variance(d) / d.length);
        double t = mean / se;
        assertEquals(-4.0621, t, 1e-4);
        assertEquals(0.002833, 2 * StudentT.cdf(t, 9), 1e-6);
        double q = StudentT.quantile(0.975, 9);
        assertEquals(-2.4598858, mean - q * se, 1e-7);
        assertEquals(-0.7001142, mean + q * se, 1e-7);
    }

    @Test
    void quantilesMatchThePrintedTable() {
        // the t table of any textbook (e.g. Abramowitz & Stegun, Table 26.10): two-sided 5 % and one-sided 20 %
        assertEquals(2.776, StudentT.quantile(0.975, 4), 5e-4);
        assertEquals(2.045, StudentT.quantile(0.975, 29), 5e-4);
        assertEquals(0.854, StudentT.quantile(0.80, 29), 5e-4);
        assertEquals(-StudentT.quantile(0.9, 7), StudentT.quantile(0.1, 7), 1e-12);
        assertEquals(0.8, StudentT.cdf(StudentT.quantile(0.8, 29), 29), 1e-14);
    }
}
