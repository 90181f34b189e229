/* tests/gen/ms_dielectric_ref.c - independent double-precision transcription of the
   dielectric random walk [Heitz16, Sec. 4-5] used to locate a discrepancy of the walk:
   own Lambda, D, Fresnel, refraction, height sampling (uniform heights, C1 = (1+h)/2,
   mirrored inside: 1 - C1) and an exact visible-normal sampler by numeric inversion
   of the visible-slope CDF in double (any side of the horizon). Compares histograms
   (8 cos x 8 phi bins per hemisphere) of: appear sampler vs reference walk, the
   reference walk vs appear_dielectric_ms_eval integrated over uniform directions,
   appear eval vs reference next-event estimate, reference walk vs reference NEE.
   Build: cc -O2 -std=c99 -I. tests/gen/ms_dielectric_ref.c -o ms_ref -lm
   Run:   ./ms_ref TYPE(0 ggx, 1 beckmann) ALPHA ETA WO_Z N_WALKS    e.g. ./ms_ref 0 1.5 1.33 -0.9 400000 */
/* independent double reference of the Heitz 2016 dielectric walk; compare
   histograms: appear sampler, reference walk, appear eval integrated, reference NEE integrated */
#define APPEAR_IMPLEMENTATION
#include "appear.h"
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include <string.h>
#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif
static unsigned long long S = 88172645463325252ULL;
static double U(void){ S ^= S << 13; S ^= S >> 7; S ^= S << 17; return (S >> 11) * (1.0 / 9007199254740992.0); }
typedef struct { double x, y, z; } v3;
static v3 V(double x,double y,double z){v3 r={x,y,z};return r;}
static double dot(v3 a, v3 b){return a.x*b.x+a.y*b.y+a.z*b.z;}
static v3 sc(v3 a,double s){return V(a.x*s,a.y*s,a.z*s);}
static v3 add(v3 a,v3 b){return V(a.x+b.x,a.y+b.y,a.z+b.z);}
static v3 nrm(v3 a){return sc(a,1/sqrt(dot(a,a)));}
static int KMIN=1, KMAX=1000; static int TY; static double AX, AY, ETA;
static double lam(v3 w){ /* Lambda of w mirrored up */
  double z=fabs(w.z), s2=w.x*w.x+w.y*w.y; if(s2<=0) return 0;
  double a2=(AX*AX*w.x*w.x+AY*AY*w.y*w.y)/s2, t2=s2/(z*z);
  if(TY==0) return 0.5*(-1+sqrt(1+a2*t2));
  double nu=1/sqrt(a2*t2); return 0.5*(erf(nu)-1)+exp(-nu*nu)/(2*nu*sqrt(M_PI));
}
static double D(v3 m){ if(m.z<=0) return 0; double z2=m.z*m.z, e=(m.x*m.x/(AX*AX)+m.y*m.y/(AY*AY))/z2;
  if(TY==0) return 1/(M_PI*AX*AY*z2*z2*(1+e)*(1+e));
  return exp(-e)/(M_PI*AX*AY*z2*z2); }
/* exact visible-normal sampler by numeric inversion in double (slope space, stretched to alpha 1,
   rotated so that wi = (s, 0, c)): x has density (c - s x)+ p(x), y | x from the conditional slope density */
static double cdfx(double x, double c, double s){ /* unnormalised */
  if(TY==0){ double q=sqrt(1+x*x); return c*(x/q+1)/2 + s/(2*q); }
  return c*(1+erf(x))/2 + s*exp(-x*x)/(2*sqrt(M_PI)); }
static v3 vndf(v3 wi){
  v3 w=nrm(V(AX*wi.x,AY*wi.y,wi.z)); double s=sqrt(w.x*w.x+w.y*w.y), c=w.z, cp=1, sp=0, bhi, lo, hi, t, x, y; int i;
  if(s>1e-14){ cp=w.x/s; sp=w.y/s; } else s=0;
  bhi = s>0? atan2(c,s) : M_PI/2; /* x < c/s */
  t = U()*cdfx(tan(bhi),c,s); lo=-M_PI/2; hi=bhi;
  for(i=0;i<80;i++){ double mid=0.5*(lo+hi); if(cdfx(tan(mid),c,s)<t) lo=mid; else hi=mid; }
  x=tan(0.5*(lo+hi));
  t=U(); lo=-M_PI/2; hi=M_PI/2;
  for(i=0;i<80;i++){ double mid=0.5*(lo+hi), v=tan(mid), g = TY==0? 0.5+(atan(v)+v/(1+v*v))/M_PI : 0.5*(1+erf(v)); if(g<t) lo=mid; else hi=mid; }
  y=tan(0.5*(lo+hi)); if(TY==0) y*=sqrt(1+x*x);
  { double sx=cp*x-sp*y, sy=sp*x+cp*y; return nrm(V(-AX*sx,-AY*sy,1)); }
}
static double area(v3 wi){ double L=lam(wi); return wi.z>0? wi.z*(1+L) : -wi.z*L; }
static double fres(double c, double e){ double s2=(1-c*c)/(e*e); if(s2>=1) return 1; double ct=sqrt(1-s2);
  double rs=(c-e*ct)/(c+e*ct), rp=(e*c-ct)/(e*c+ct); return 0.5*(rs*rs+rp*rp); }
/* walk; nee target wt (world) accumulates into *acc; returns exit dir (world) */
static int walk(v3 wo, v3 *out, int nee, v3 wt, double *acc){
  double sg = wo.z>0?1:-1, h=sg; /* h: height in outside coords, C1 = (1+h)/2 uniform on [-1,1] */
  v3 d = sc(wo,-1); /* world direction of travel */
  int k;
  for(k=0;k<1000;k++){
    v3 f = sc(d,sg); double e = sg>0?ETA:1/ETA; double L=lam(f);
    double C = 0.5*(1+sg*h); /* current frame */
    double u=U();
    if(f.z>0){ double Cn = C*pow(u,-1/L); if(!(L>0) || Cn>=1){ *out=d; return k; } C=Cn; }
    else C = C*pow(u,1/(1+L));
    h = sg*(2*C-1);
    v3 wi = sc(f,-1);
    if(nee && k+1>=KMIN && k+1<=KMAX){ v3 tf=sc(wt,sg); double A=area(wi), Lt=lam(wt);
      if(tf.z>0){ v3 m=nrm(add(wi,tf)); double dm=dot(wi,m); if(m.z>0&&dm>0) *acc += fres(dm,e)*D(m)/(4*A)*pow(C,Lt); }
      else { v3 m=nrm(add(wi,sc(tf,e))); if(m.z<0) m=sc(m,-1); double dm=dot(wi,m), dt=dot(tf,m);
        if(dm>0&&dt<0){ double den=dm+e*dt; *acc += (1-fres(dm,e))*dm*D(m)/A * e*e*(-dt)/(den*den) * pow(1-C,Lt); } }
    }
    v3 m=vndf(wi); double dm=dot(wi,m), F=fres(dm,e);
    if(U()<F){ f = add(sc(m,2*dm),sc(wi,-1)); d=sc(f,sg); }
    else { double ct=sqrt(1-(1-dm*dm)/(e*e)); f = add(sc(wi,-1/e), sc(m, dm/e-ct)); d=sc(f,sg); sg=-sg; }
  }
  return -1;
}
enum{NZ=8,NP=8,NB=2*NZ*NP};
static int bin(double x,double y,double z){ int iz=(int)fmin(NZ-1,fabs(z)*NZ), ip=(int)fmin(NP-1,(atan2(y,x)+M_PI)/(2*M_PI)*NP); return (z<0?NZ*NP:0)+iz*NP+ip; }
static void cmp(const char*n, double*a, double na, double*b, double*b2, double nb){ double chi=0; int dof=0,i;
  for(i=0;i<NB;i++){ double ea=a[i]/na, eb=b[i]/nb; double va=a[i]/(na*na), vb= b2? b2[i]/(nb*nb) : b[i]/(nb*nb); if(a[i]+b[i]<40) continue; chi+=(ea-eb)*(ea-eb)/(va+vb); dof++; }
  printf("  %-40s chi2 %.1f dof %d  z %.1f\n", n, chi, dof, (chi-dof)/sqrt(2.0*dof)); }
int main(int argc,char**argv){
  TY=atoi(argv[1]); AX=AY=atof(argv[2]); ETA=atof(argv[3]); double wz=atof(argv[4]); long n=atol(argv[5]);
  v3 wo=V(sqrt(1-wz*wz),0,wz);
  appear_dielectric m=appear_dielectric_make(appear_microfacet_make(TY,(float)AX,(float)AY,APPEAR_SAMPLE_VISIBLE),(float)ETA);
  appear_vec3 wof=appear_vec3_make((float)wo.x,0,(float)wo.z);
  static double hs[NB], hr[NB], he[NB], he2[NB], hn[NB], hn2[NB]; long i; appear_rng rng=appear_rng_make(5);
  for(i=0;i<n;i++){ appear_bsdf_record s; if(appear_dielectric_ms_sample(&m,wof,&rng,&s)) hs[bin(s.wi.x,s.wi.y,s.wi.z)]+=1;
    v3 o; if(walk(wo,&o,0,wo,0)>=1) hr[bin(o.x,o.y,o.z)]+=1; }
  cmp("appear sampler vs ref walk", hs,n,hr,0,n);
  /* integrated evals: wi uniform on the sphere */
  long ne=n/4; double tot_e=0, tot_n=0;
  for(i=0;i<ne;i++){ double z=2*U()-1, r=sqrt(1-z*z), p=2*M_PI*U(); v3 w=V(r*cos(p),r*sin(p),z);
    double fl = (w.z*wo.z<0)? (wo.z>0?ETA*ETA:1/(ETA*ETA)) : 1;
    double v = appear_dielectric_ms_eval(&m,wof,appear_vec3_make((float)w.x,(float)w.y,(float)w.z),&rng).v[0]*fabs(w.z)*fl*4*M_PI;
    int b=bin(w.x,w.y,w.z); he[b]+=v; he2[b]+=v*v; tot_e+=v;
    double acc=0; v3 o; walk(wo,&o,1,w,&acc); v=acc*4*M_PI; hn[b]+=v; hn2[b]+=v*v; tot_n+=v; }
  cmp("ref walk vs appear eval", hr,n,he,he2,ne); for(i=0;i<NB;i++){ double a=hr[i]/n, b=he[i]/ne, v=hr[i]/((double)n*n)+ (he2[i]/ne - b*b)/ne; if(fabs(a-b)>2.5*sqrt(v)) printf("   bin %s zb %ld pb %ld walk %.5f eval %.5f z %.1f\n", i<NZ*NP?"up":"dn", (i%(NZ*NP))/NP, i%NP, a,b,(b-a)/sqrt(v)); }
  for(i=0;i<NB;i++){ he2[i]=he2[i]; }
  { double chi=0; int dof=0; for(i=0;i<NB;i++){ double ea=he[i]/ne, eb=hn[i]/ne, v=(he2[i]+hn2[i])/((double)ne*ne); if(v<=0||hr[i]<40) continue; chi+=(ea-eb)*(ea-eb)/v; dof++; } printf("  %-40s chi2 %.1f dof %d z %.1f\n","appear eval vs ref NEE",chi,dof,(chi-dof)/sqrt(2.0*dof)); }
  { double chi=0; int dof=0; for(i=0;i<NB;i++){ double ea=hr[i]/n, eb=hn[i]/ne, v=hr[i]/((double)n*n)+hn2[i]/((double)ne*ne); if(hr[i]<40) continue; chi+=(ea-eb)*(ea-eb)/v; dof++; } printf("  %-40s chi2 %.1f dof %d z %.1f\n","ref walk vs ref NEE",chi,dof,(chi-dof)/sqrt(2.0*dof)); }
  printf("  totals: eval %.4f refNEE %.4f\n", tot_e/ne, tot_n/ne);
  return 0;
}
