# Reference values for QuantilesExactnessTest: mpmath at 50 digits, inputs taken as the exact doubles Java uses.
from mpmath import mp, mpf, betainc, findroot, erfc, erfinv, sqrt, tan, pi
from scipy import stats
mp.dps = 50
def beta_lower_inv(p, a, b):   # x with I_x(a,b) = p
    x0 = stats.beta.ppf(float(p), float(a), float(b))
    return findroot(lambda x: betainc(a, b, 0, x, regularized=True) - p, mpf(x0), tol=mpf(10)**-45)
def beta_upper_inv(q, a, b):   # x with I_{1-x}(b,a) = q
    x0 = stats.beta.isf(float(q), float(a), float(b))
    return findroot(lambda x: betainc(b, a, 0, 1-x, regularized=True) - q, mpf(x0), tol=mpf(10)**-45)
print("# Clopper-Pearson: level, f, n, lower, upper")
for level in (0.95, 0.99, 0.9):
    alpha = 1.0 - level; q = alpha / 2.0
    for f, n in ((1,40),(3,40),(0,40),(40,40),(39,40),(20,40),(1,2),(0,1),(1,1),(5,200),(2,7)):
        lo = 0 if f == 0 else beta_lower_inv(mpf(q), mpf(f), mpf(n-f+1))
        hi = 1 if f == n else beta_upper_inv(mpf(q), mpf(f+1), mpf(n-f))
        print("{%r, %d, %d, %s, %s}," % (level, f, n, mp.nstr(lo, 20), mp.nstr(hi, 20)))
print("# t upper quantile: q, df, t")
def t_upper(q, df):
    x0 = stats.t.isf(float(q), df)
    return findroot(lambda t: betainc(mpf(df)/2, mpf(1)/2, 0, df/(df+t*t), regularized=True)/2 - q, mpf(x0), tol=mpf(10)**-45)
for q in ((1-0.95)/2, (1-0.9)/2, (1-0.99)/2, 0.2, 0.3, 0.45, 1e-8):
    for df in (1,2,3,4,7,29,55,100):
        print("{%r, %d, %s}," % (q, df, mp.nstr(t_upper(mpf(q), df), 20)))
print("# normal upper quantile: q, z")
for q in ((1-0.95)/2, (1-0.9)/2, (1-0.99)/2, 0.2, 0.45, 1e-10, 1e-20):
    print("{%r, %s}," % (q, mp.nstr(-sqrt(2)*erfinv(2*mpf(q)-1), 20)))
print("# normal upper tail: z, Q(z)")
for z in (0.0, 1.0, 1.959963984540054, 3.0, 6.21, 8.5, 20.0, 37.0):
    print("{%r, %s}," % (z, mp.nstr(erfc(mpf(z)/sqrt(2))/2, 20)))
