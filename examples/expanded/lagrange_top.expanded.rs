/// The Lagrange top: a heavy symmetric top about a fixed point on its axis.
#[derive(Lagrangian)]
#[lagrangian(
    kinetic = 0.5*(a1*(omega.x*omega.x+omega.y*omega.y)+c*omega.z*omega.z),
    potential = mgl*gamma.z,
)]
pub struct LagrangeTop {
    /// Equatorial moment of inertia A₁ about the fixed point.
    pub a1: f64,
    /// Axial moment of inertia C.
    pub c: f64,
    /// m g l: weight times the distance of the centre of mass from the fixed point.
    pub mgl: f64,
}
#[doc(hidden)]
#[allow(
    non_upper_case_globals,
    unused_qualifications,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
const _: () = {
    #[automatically_derived]
    impl ::routh::__private::Lagrangian for LagrangeTop {
        #[inline]
        fn lagrangian(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __omega[0usize];
            let __v1: ::routh::__private::f64 = __omega[1usize];
            let __v2: ::routh::__private::f64 = __omega[2usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t11: ::routh::__private::f64 = __v0 * __v0;
            let __t12: ::routh::__private::f64 = __v1 * __v1;
            let __t13: ::routh::__private::f64 = __t11 + __t12;
            let __t14: ::routh::__private::f64 = __v7 * __t13;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t16: ::routh::__private::f64 = __v2 * __t15;
            let __t17: ::routh::__private::f64 = __t14 + __t16;
            let __t18: ::routh::__private::f64 = 0.5f64 * __t17;
            let __t19: ::routh::__private::f64 = __v5 * __v9;
            let __t22: ::routh::__private::f64 = __t18 - __t19;
            __t22
        }
        #[inline]
        fn dl_domega(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::Vector3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __omega[0usize];
            let __v1: ::routh::__private::f64 = __omega[1usize];
            let __v2: ::routh::__private::f64 = __omega[2usize];
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            ::routh::__private::Vector3::new(__t26, __t29, __t15)
        }
        #[inline]
        fn dl_dgamma(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::Vector3<::routh::__private::f64> {
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t32: ::routh::__private::f64 = -__v9;
            ::routh::__private::Vector3::new(0f64, 0f64, __t32)
        }
        #[inline]
        fn d2l_domega2(
            &self,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::Matrix3<::routh::__private::f64> {
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            ::routh::__private::Matrix3::new(
                __v7,
                0f64,
                0f64,
                0f64,
                __v7,
                0f64,
                0f64,
                0f64,
                __v8,
            )
        }
        #[inline]
        fn d2l_domega_dgamma(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::Matrix3<::routh::__private::f64> {
            ::routh::__private::Matrix3::new(
                0f64,
                0f64,
                0f64,
                0f64,
                0f64,
                0f64,
                0f64,
                0f64,
                0f64,
            )
        }
        #[inline]
        fn energy(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __omega[0usize];
            let __v1: ::routh::__private::f64 = __omega[1usize];
            let __v2: ::routh::__private::f64 = __omega[2usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t11: ::routh::__private::f64 = __v0 * __v0;
            let __t12: ::routh::__private::f64 = __v1 * __v1;
            let __t13: ::routh::__private::f64 = __t11 + __t12;
            let __t14: ::routh::__private::f64 = __v7 * __t13;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t16: ::routh::__private::f64 = __v2 * __t15;
            let __t17: ::routh::__private::f64 = __t14 + __t16;
            let __t18: ::routh::__private::f64 = 0.5f64 * __t17;
            let __t19: ::routh::__private::f64 = __v5 * __v9;
            let __t22: ::routh::__private::f64 = __t18 - __t19;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t33: ::routh::__private::f64 = __v0 * __t26;
            let __t34: ::routh::__private::f64 = __v1 * __t29;
            let __t35: ::routh::__private::f64 = __t33 + __t34;
            let __t36: ::routh::__private::f64 = __t16 + __t35;
            let __t38: ::routh::__private::f64 = __t36 - __t22;
            __t38
        }
        #[inline]
        fn cyclic_momentum(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __omega[0usize];
            let __v1: ::routh::__private::f64 = __omega[1usize];
            let __v2: ::routh::__private::f64 = __omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t55: ::routh::__private::f64 = __v5 * __v8;
            let __t69: ::routh::__private::f64 = __v5 * __t15;
            let __t70: ::routh::__private::f64 = __v2 * __t55;
            let __t71: ::routh::__private::f64 = __t69 + __t70;
            let __t72: ::routh::__private::f64 = __v1 * __v4;
            let __t73: ::routh::__private::f64 = 2f64 * __t72;
            let __t74: ::routh::__private::f64 = __v0 * __v3;
            let __t75: ::routh::__private::f64 = 2f64 * __t74;
            let __t76: ::routh::__private::f64 = __t73 + __t75;
            let __t77: ::routh::__private::f64 = __v7 * __t76;
            let __t78: ::routh::__private::f64 = __t71 + __t77;
            let __t79: ::routh::__private::f64 = 0.5f64 * __t78;
            __t79
        }
    }
    #[automatically_derived]
    impl ::routh::__private::Routhian for LagrangeTop {
        #[inline]
        fn psi_dot(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t55: ::routh::__private::f64 = __v5 * __v8;
            let __t69: ::routh::__private::f64 = __v5 * __t15;
            let __t70: ::routh::__private::f64 = __v2 * __t55;
            let __t71: ::routh::__private::f64 = __t69 + __t70;
            let __t72: ::routh::__private::f64 = __v1 * __v4;
            let __t73: ::routh::__private::f64 = 2f64 * __t72;
            let __t74: ::routh::__private::f64 = __v0 * __v3;
            let __t75: ::routh::__private::f64 = 2f64 * __t74;
            let __t76: ::routh::__private::f64 = __t73 + __t75;
            let __t77: ::routh::__private::f64 = __v7 * __t76;
            let __t78: ::routh::__private::f64 = __t71 + __t77;
            let __t80: ::routh::__private::f64 = __v3 * __v3;
            let __t81: ::routh::__private::f64 = __v4 * __v4;
            let __t82: ::routh::__private::f64 = __t80 + __t81;
            let __t83: ::routh::__private::f64 = __v7 * __t82;
            let __t84: ::routh::__private::f64 = __v5 * __t55;
            let __t85: ::routh::__private::f64 = __t83 + __t84;
            let __t88: ::routh::__private::f64 = (-0.5f64) * __t78;
            let __t89: ::routh::__private::f64 = __v6 + __t88;
            let __t91: ::routh::__private::f64 = __t89 / __t85;
            __t91
        }
        #[inline]
        fn routhian(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t11: ::routh::__private::f64 = __v0 * __v0;
            let __t12: ::routh::__private::f64 = __v1 * __v1;
            let __t13: ::routh::__private::f64 = __t11 + __t12;
            let __t14: ::routh::__private::f64 = __v7 * __t13;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t16: ::routh::__private::f64 = __v2 * __t15;
            let __t17: ::routh::__private::f64 = __t14 + __t16;
            let __t18: ::routh::__private::f64 = 0.5f64 * __t17;
            let __t19: ::routh::__private::f64 = __v5 * __v9;
            let __t22: ::routh::__private::f64 = __t18 - __t19;
            let __t55: ::routh::__private::f64 = __v5 * __v8;
            let __t69: ::routh::__private::f64 = __v5 * __t15;
            let __t70: ::routh::__private::f64 = __v2 * __t55;
            let __t71: ::routh::__private::f64 = __t69 + __t70;
            let __t72: ::routh::__private::f64 = __v1 * __v4;
            let __t73: ::routh::__private::f64 = 2f64 * __t72;
            let __t74: ::routh::__private::f64 = __v0 * __v3;
            let __t75: ::routh::__private::f64 = 2f64 * __t74;
            let __t76: ::routh::__private::f64 = __t73 + __t75;
            let __t77: ::routh::__private::f64 = __v7 * __t76;
            let __t78: ::routh::__private::f64 = __t71 + __t77;
            let __t80: ::routh::__private::f64 = __v3 * __v3;
            let __t81: ::routh::__private::f64 = __v4 * __v4;
            let __t82: ::routh::__private::f64 = __t80 + __t81;
            let __t83: ::routh::__private::f64 = __v7 * __t82;
            let __t84: ::routh::__private::f64 = __v5 * __t55;
            let __t85: ::routh::__private::f64 = __t83 + __t84;
            let __t88: ::routh::__private::f64 = (-0.5f64) * __t78;
            let __t89: ::routh::__private::f64 = __v6 + __t88;
            let __t91: ::routh::__private::f64 = __t89 / __t85;
            let __t93: ::routh::__private::f64 = __t89 * __t91;
            let __t95: ::routh::__private::f64 = (-0.5f64) * __t93;
            let __t96: ::routh::__private::f64 = __t22 + __t95;
            __t96
        }
        #[inline]
        fn dr_domega(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::Vector3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t55: ::routh::__private::f64 = __v5 * __v8;
            let __t69: ::routh::__private::f64 = __v5 * __t15;
            let __t70: ::routh::__private::f64 = __v2 * __t55;
            let __t71: ::routh::__private::f64 = __t69 + __t70;
            let __t72: ::routh::__private::f64 = __v1 * __v4;
            let __t73: ::routh::__private::f64 = 2f64 * __t72;
            let __t74: ::routh::__private::f64 = __v0 * __v3;
            let __t75: ::routh::__private::f64 = 2f64 * __t74;
            let __t76: ::routh::__private::f64 = __t73 + __t75;
            let __t77: ::routh::__private::f64 = __v7 * __t76;
            let __t78: ::routh::__private::f64 = __t71 + __t77;
            let __t80: ::routh::__private::f64 = __v3 * __v3;
            let __t81: ::routh::__private::f64 = __v4 * __v4;
            let __t82: ::routh::__private::f64 = __t80 + __t81;
            let __t83: ::routh::__private::f64 = __v7 * __t82;
            let __t84: ::routh::__private::f64 = __v5 * __t55;
            let __t85: ::routh::__private::f64 = __t83 + __t84;
            let __t88: ::routh::__private::f64 = (-0.5f64) * __t78;
            let __t89: ::routh::__private::f64 = __v6 + __t88;
            let __t91: ::routh::__private::f64 = __t89 / __t85;
            let __t106: ::routh::__private::f64 = __v3 * __v7;
            let __t112: ::routh::__private::f64 = __v4 * __v7;
            let __t209: ::routh::__private::f64 = __t91 * __t106;
            let __t211: ::routh::__private::f64 = __t26 + __t209;
            let __t212: ::routh::__private::f64 = __t91 * __t112;
            let __t214: ::routh::__private::f64 = __t29 + __t212;
            let __t215: ::routh::__private::f64 = __t55 * __t91;
            let __t217: ::routh::__private::f64 = __t15 + __t215;
            ::routh::__private::Vector3::new(__t211, __t214, __t217)
        }
        #[inline]
        fn dr_dgamma(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::Vector3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t55: ::routh::__private::f64 = __v5 * __v8;
            let __t69: ::routh::__private::f64 = __v5 * __t15;
            let __t70: ::routh::__private::f64 = __v2 * __t55;
            let __t71: ::routh::__private::f64 = __t69 + __t70;
            let __t72: ::routh::__private::f64 = __v1 * __v4;
            let __t73: ::routh::__private::f64 = 2f64 * __t72;
            let __t74: ::routh::__private::f64 = __v0 * __v3;
            let __t75: ::routh::__private::f64 = 2f64 * __t74;
            let __t76: ::routh::__private::f64 = __t73 + __t75;
            let __t77: ::routh::__private::f64 = __v7 * __t76;
            let __t78: ::routh::__private::f64 = __t71 + __t77;
            let __t80: ::routh::__private::f64 = __v3 * __v3;
            let __t81: ::routh::__private::f64 = __v4 * __v4;
            let __t82: ::routh::__private::f64 = __t80 + __t81;
            let __t83: ::routh::__private::f64 = __v7 * __t82;
            let __t84: ::routh::__private::f64 = __v5 * __t55;
            let __t85: ::routh::__private::f64 = __t83 + __t84;
            let __t88: ::routh::__private::f64 = (-0.5f64) * __t78;
            let __t89: ::routh::__private::f64 = __v6 + __t88;
            let __t91: ::routh::__private::f64 = __t89 / __t85;
            let __t106: ::routh::__private::f64 = __v3 * __v7;
            let __t112: ::routh::__private::f64 = __v4 * __v7;
            let __t202: ::routh::__private::f64 = __t91 * __t91;
            let __t218: ::routh::__private::f64 = __t26 * __t91;
            let __t220: ::routh::__private::f64 = __t106 * __t202;
            let __t222: ::routh::__private::f64 = __t218 + __t220;
            let __t223: ::routh::__private::f64 = __t29 * __t91;
            let __t225: ::routh::__private::f64 = __t112 * __t202;
            let __t227: ::routh::__private::f64 = __t223 + __t225;
            let __t228: ::routh::__private::f64 = __t15 * __t91;
            let __t230: ::routh::__private::f64 = __t228 - __v9;
            let __t231: ::routh::__private::f64 = __t55 * __t202;
            let __t233: ::routh::__private::f64 = __t230 + __t231;
            ::routh::__private::Vector3::new(__t222, __t227, __t233)
        }
        #[inline]
        fn dr_dp(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t55: ::routh::__private::f64 = __v5 * __v8;
            let __t69: ::routh::__private::f64 = __v5 * __t15;
            let __t70: ::routh::__private::f64 = __v2 * __t55;
            let __t71: ::routh::__private::f64 = __t69 + __t70;
            let __t72: ::routh::__private::f64 = __v1 * __v4;
            let __t73: ::routh::__private::f64 = 2f64 * __t72;
            let __t74: ::routh::__private::f64 = __v0 * __v3;
            let __t75: ::routh::__private::f64 = 2f64 * __t74;
            let __t76: ::routh::__private::f64 = __t73 + __t75;
            let __t77: ::routh::__private::f64 = __v7 * __t76;
            let __t78: ::routh::__private::f64 = __t71 + __t77;
            let __t80: ::routh::__private::f64 = __v3 * __v3;
            let __t81: ::routh::__private::f64 = __v4 * __v4;
            let __t82: ::routh::__private::f64 = __t80 + __t81;
            let __t83: ::routh::__private::f64 = __v7 * __t82;
            let __t84: ::routh::__private::f64 = __v5 * __t55;
            let __t85: ::routh::__private::f64 = __t83 + __t84;
            let __t88: ::routh::__private::f64 = (-0.5f64) * __t78;
            let __t89: ::routh::__private::f64 = __v6 + __t88;
            let __t91: ::routh::__private::f64 = __t89 / __t85;
            let __t281: ::routh::__private::f64 = -__t91;
            __t281
        }
        #[inline]
        fn d2r_domega2(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::Matrix3<::routh::__private::f64> {
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t55: ::routh::__private::f64 = __v5 * __v8;
            let __t80: ::routh::__private::f64 = __v3 * __v3;
            let __t81: ::routh::__private::f64 = __v4 * __v4;
            let __t82: ::routh::__private::f64 = __t80 + __t81;
            let __t83: ::routh::__private::f64 = __v7 * __t82;
            let __t84: ::routh::__private::f64 = __v5 * __t55;
            let __t85: ::routh::__private::f64 = __t83 + __t84;
            let __t90: ::routh::__private::f64 = 1.0f64 / __t85;
            let __t106: ::routh::__private::f64 = __v3 * __v7;
            let __t112: ::routh::__private::f64 = __v4 * __v7;
            let __t141: ::routh::__private::f64 = __t90 * __t106;
            let __t142: ::routh::__private::f64 = __t90 * __t112;
            let __t143: ::routh::__private::f64 = __t55 * __t90;
            let __t147: ::routh::__private::f64 = __t106 * __t141;
            let __t149: ::routh::__private::f64 = __v7 - __t147;
            let __t150: ::routh::__private::f64 = __t112 * __t141;
            let __t151: ::routh::__private::f64 = -__t150;
            let __t152: ::routh::__private::f64 = __t55 * __t141;
            let __t153: ::routh::__private::f64 = -__t152;
            let __t162: ::routh::__private::f64 = __t112 * __t142;
            let __t164: ::routh::__private::f64 = __v7 - __t162;
            let __t165: ::routh::__private::f64 = __t55 * __t142;
            let __t166: ::routh::__private::f64 = -__t165;
            let __t174: ::routh::__private::f64 = __t55 * __t143;
            let __t176: ::routh::__private::f64 = __v8 - __t174;
            ::routh::__private::Matrix3::new(
                __t149,
                __t151,
                __t153,
                __t151,
                __t164,
                __t166,
                __t153,
                __t166,
                __t176,
            )
        }
        #[inline]
        fn d2r_domega_dgamma(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::Matrix3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t55: ::routh::__private::f64 = __v5 * __v8;
            let __t69: ::routh::__private::f64 = __v5 * __t15;
            let __t70: ::routh::__private::f64 = __v2 * __t55;
            let __t71: ::routh::__private::f64 = __t69 + __t70;
            let __t72: ::routh::__private::f64 = __v1 * __v4;
            let __t73: ::routh::__private::f64 = 2f64 * __t72;
            let __t74: ::routh::__private::f64 = __v0 * __v3;
            let __t75: ::routh::__private::f64 = 2f64 * __t74;
            let __t76: ::routh::__private::f64 = __t73 + __t75;
            let __t77: ::routh::__private::f64 = __v7 * __t76;
            let __t78: ::routh::__private::f64 = __t71 + __t77;
            let __t80: ::routh::__private::f64 = __v3 * __v3;
            let __t81: ::routh::__private::f64 = __v4 * __v4;
            let __t82: ::routh::__private::f64 = __t80 + __t81;
            let __t83: ::routh::__private::f64 = __v7 * __t82;
            let __t84: ::routh::__private::f64 = __v5 * __t55;
            let __t85: ::routh::__private::f64 = __t83 + __t84;
            let __t88: ::routh::__private::f64 = (-0.5f64) * __t78;
            let __t89: ::routh::__private::f64 = __v6 + __t88;
            let __t90: ::routh::__private::f64 = 1.0f64 / __t85;
            let __t91: ::routh::__private::f64 = __t89 * __t90;
            let __t106: ::routh::__private::f64 = __v3 * __v7;
            let __t112: ::routh::__private::f64 = __v4 * __v7;
            let __t141: ::routh::__private::f64 = __t90 * __t106;
            let __t142: ::routh::__private::f64 = __t90 * __t112;
            let __t143: ::routh::__private::f64 = __t55 * __t90;
            let __t209: ::routh::__private::f64 = __t91 * __t106;
            let __t210: ::routh::__private::f64 = 2f64 * __t209;
            let __t212: ::routh::__private::f64 = __t91 * __t112;
            let __t213: ::routh::__private::f64 = 2f64 * __t212;
            let __t215: ::routh::__private::f64 = __t55 * __t91;
            let __t216: ::routh::__private::f64 = 2f64 * __t215;
            let __t235: ::routh::__private::f64 = __t26 + __t210;
            let __t236: ::routh::__private::f64 = __t29 + __t213;
            let __t237: ::routh::__private::f64 = __t15 + __t216;
            let __t241: ::routh::__private::f64 = __v7 * __t91;
            let __t242: ::routh::__private::f64 = __t141 * __t235;
            let __t244: ::routh::__private::f64 = __t241 - __t242;
            let __t245: ::routh::__private::f64 = __t141 * __t236;
            let __t246: ::routh::__private::f64 = -__t245;
            let __t247: ::routh::__private::f64 = __t141 * __t237;
            let __t248: ::routh::__private::f64 = -__t247;
            let __t249: ::routh::__private::f64 = __t142 * __t235;
            let __t250: ::routh::__private::f64 = -__t249;
            let __t251: ::routh::__private::f64 = __t142 * __t236;
            let __t253: ::routh::__private::f64 = __t241 - __t251;
            let __t254: ::routh::__private::f64 = __t142 * __t237;
            let __t255: ::routh::__private::f64 = -__t254;
            let __t256: ::routh::__private::f64 = __t143 * __t235;
            let __t257: ::routh::__private::f64 = -__t256;
            let __t258: ::routh::__private::f64 = __t143 * __t236;
            let __t259: ::routh::__private::f64 = -__t258;
            let __t260: ::routh::__private::f64 = __v8 * __t91;
            let __t261: ::routh::__private::f64 = __t143 * __t237;
            let __t263: ::routh::__private::f64 = __t260 - __t261;
            ::routh::__private::Matrix3::new(
                __t244,
                __t246,
                __t248,
                __t250,
                __t253,
                __t255,
                __t257,
                __t259,
                __t263,
            )
        }
        #[inline]
        fn d2r_dgamma2(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::Matrix3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t55: ::routh::__private::f64 = __v5 * __v8;
            let __t69: ::routh::__private::f64 = __v5 * __t15;
            let __t70: ::routh::__private::f64 = __v2 * __t55;
            let __t71: ::routh::__private::f64 = __t69 + __t70;
            let __t72: ::routh::__private::f64 = __v1 * __v4;
            let __t73: ::routh::__private::f64 = 2f64 * __t72;
            let __t74: ::routh::__private::f64 = __v0 * __v3;
            let __t75: ::routh::__private::f64 = 2f64 * __t74;
            let __t76: ::routh::__private::f64 = __t73 + __t75;
            let __t77: ::routh::__private::f64 = __v7 * __t76;
            let __t78: ::routh::__private::f64 = __t71 + __t77;
            let __t80: ::routh::__private::f64 = __v3 * __v3;
            let __t81: ::routh::__private::f64 = __v4 * __v4;
            let __t82: ::routh::__private::f64 = __t80 + __t81;
            let __t83: ::routh::__private::f64 = __v7 * __t82;
            let __t84: ::routh::__private::f64 = __v5 * __t55;
            let __t85: ::routh::__private::f64 = __t83 + __t84;
            let __t88: ::routh::__private::f64 = (-0.5f64) * __t78;
            let __t89: ::routh::__private::f64 = __v6 + __t88;
            let __t90: ::routh::__private::f64 = 1.0f64 / __t85;
            let __t91: ::routh::__private::f64 = __t89 * __t90;
            let __t106: ::routh::__private::f64 = __v3 * __v7;
            let __t112: ::routh::__private::f64 = __v4 * __v7;
            let __t202: ::routh::__private::f64 = __t91 * __t91;
            let __t209: ::routh::__private::f64 = __t91 * __t106;
            let __t210: ::routh::__private::f64 = 2f64 * __t209;
            let __t212: ::routh::__private::f64 = __t91 * __t112;
            let __t213: ::routh::__private::f64 = 2f64 * __t212;
            let __t215: ::routh::__private::f64 = __t55 * __t91;
            let __t216: ::routh::__private::f64 = 2f64 * __t215;
            let __t235: ::routh::__private::f64 = __t26 + __t210;
            let __t236: ::routh::__private::f64 = __t29 + __t213;
            let __t237: ::routh::__private::f64 = __t15 + __t216;
            let __t238: ::routh::__private::f64 = __t90 * __t235;
            let __t239: ::routh::__private::f64 = __t90 * __t236;
            let __t240: ::routh::__private::f64 = __t90 * __t237;
            let __t264: ::routh::__private::f64 = __v7 * __t202;
            let __t265: ::routh::__private::f64 = __t235 * __t238;
            let __t267: ::routh::__private::f64 = __t264 - __t265;
            let __t268: ::routh::__private::f64 = __t236 * __t238;
            let __t269: ::routh::__private::f64 = -__t268;
            let __t270: ::routh::__private::f64 = __t237 * __t238;
            let __t271: ::routh::__private::f64 = -__t270;
            let __t272: ::routh::__private::f64 = __t236 * __t239;
            let __t274: ::routh::__private::f64 = __t264 - __t272;
            let __t275: ::routh::__private::f64 = __t237 * __t239;
            let __t276: ::routh::__private::f64 = -__t275;
            let __t277: ::routh::__private::f64 = __v8 * __t202;
            let __t278: ::routh::__private::f64 = __t237 * __t240;
            let __t280: ::routh::__private::f64 = __t277 - __t278;
            ::routh::__private::Matrix3::new(
                __t267,
                __t269,
                __t271,
                __t269,
                __t274,
                __t276,
                __t271,
                __t276,
                __t280,
            )
        }
        #[inline]
        fn amended_potential(
            &self,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::f64 {
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t19: ::routh::__private::f64 = __v5 * __v9;
            let __t55: ::routh::__private::f64 = __v5 * __v8;
            let __t80: ::routh::__private::f64 = __v3 * __v3;
            let __t81: ::routh::__private::f64 = __v4 * __v4;
            let __t82: ::routh::__private::f64 = __t80 + __t81;
            let __t83: ::routh::__private::f64 = __v7 * __t82;
            let __t84: ::routh::__private::f64 = __v5 * __t55;
            let __t85: ::routh::__private::f64 = __t83 + __t84;
            let __t304: ::routh::__private::f64 = __v6 / __t85;
            let __t306: ::routh::__private::f64 = __v6 * __t304;
            let __t308: ::routh::__private::f64 = (-0.5f64) * __t306;
            let __t309: ::routh::__private::f64 = __t308 - __t19;
            let __t463: ::routh::__private::f64 = -__t309;
            __t463
        }
        #[inline]
        fn bundle(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::RouthBundle {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t11: ::routh::__private::f64 = __v0 * __v0;
            let __t12: ::routh::__private::f64 = __v1 * __v1;
            let __t13: ::routh::__private::f64 = __t11 + __t12;
            let __t14: ::routh::__private::f64 = __v7 * __t13;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t16: ::routh::__private::f64 = __v2 * __t15;
            let __t17: ::routh::__private::f64 = __t14 + __t16;
            let __t18: ::routh::__private::f64 = 0.5f64 * __t17;
            let __t19: ::routh::__private::f64 = __v5 * __v9;
            let __t22: ::routh::__private::f64 = __t18 - __t19;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t55: ::routh::__private::f64 = __v5 * __v8;
            let __t69: ::routh::__private::f64 = __v5 * __t15;
            let __t70: ::routh::__private::f64 = __v2 * __t55;
            let __t71: ::routh::__private::f64 = __t69 + __t70;
            let __t72: ::routh::__private::f64 = __v1 * __v4;
            let __t73: ::routh::__private::f64 = 2f64 * __t72;
            let __t74: ::routh::__private::f64 = __v0 * __v3;
            let __t75: ::routh::__private::f64 = 2f64 * __t74;
            let __t76: ::routh::__private::f64 = __t73 + __t75;
            let __t77: ::routh::__private::f64 = __v7 * __t76;
            let __t78: ::routh::__private::f64 = __t71 + __t77;
            let __t80: ::routh::__private::f64 = __v3 * __v3;
            let __t81: ::routh::__private::f64 = __v4 * __v4;
            let __t82: ::routh::__private::f64 = __t80 + __t81;
            let __t83: ::routh::__private::f64 = __v7 * __t82;
            let __t84: ::routh::__private::f64 = __v5 * __t55;
            let __t85: ::routh::__private::f64 = __t83 + __t84;
            let __t88: ::routh::__private::f64 = (-0.5f64) * __t78;
            let __t89: ::routh::__private::f64 = __v6 + __t88;
            let __t90: ::routh::__private::f64 = 1.0f64 / __t85;
            let __t91: ::routh::__private::f64 = __t89 * __t90;
            let __t93: ::routh::__private::f64 = __t89 * __t91;
            let __t95: ::routh::__private::f64 = (-0.5f64) * __t93;
            let __t96: ::routh::__private::f64 = __t22 + __t95;
            let __t106: ::routh::__private::f64 = __v3 * __v7;
            let __t112: ::routh::__private::f64 = __v4 * __v7;
            let __t141: ::routh::__private::f64 = __t90 * __t106;
            let __t142: ::routh::__private::f64 = __t90 * __t112;
            let __t143: ::routh::__private::f64 = __t55 * __t90;
            let __t147: ::routh::__private::f64 = __t106 * __t141;
            let __t149: ::routh::__private::f64 = __v7 - __t147;
            let __t150: ::routh::__private::f64 = __t112 * __t141;
            let __t151: ::routh::__private::f64 = -__t150;
            let __t152: ::routh::__private::f64 = __t55 * __t141;
            let __t153: ::routh::__private::f64 = -__t152;
            let __t162: ::routh::__private::f64 = __t112 * __t142;
            let __t164: ::routh::__private::f64 = __v7 - __t162;
            let __t165: ::routh::__private::f64 = __t55 * __t142;
            let __t166: ::routh::__private::f64 = -__t165;
            let __t174: ::routh::__private::f64 = __t55 * __t143;
            let __t176: ::routh::__private::f64 = __v8 - __t174;
            let __t202: ::routh::__private::f64 = __t91 * __t91;
            let __t209: ::routh::__private::f64 = __t91 * __t106;
            let __t210: ::routh::__private::f64 = 2f64 * __t209;
            let __t211: ::routh::__private::f64 = __t26 + __t209;
            let __t212: ::routh::__private::f64 = __t91 * __t112;
            let __t213: ::routh::__private::f64 = 2f64 * __t212;
            let __t214: ::routh::__private::f64 = __t29 + __t212;
            let __t215: ::routh::__private::f64 = __t55 * __t91;
            let __t216: ::routh::__private::f64 = 2f64 * __t215;
            let __t217: ::routh::__private::f64 = __t15 + __t215;
            let __t218: ::routh::__private::f64 = __t26 * __t91;
            let __t220: ::routh::__private::f64 = __t106 * __t202;
            let __t222: ::routh::__private::f64 = __t218 + __t220;
            let __t223: ::routh::__private::f64 = __t29 * __t91;
            let __t225: ::routh::__private::f64 = __t112 * __t202;
            let __t227: ::routh::__private::f64 = __t223 + __t225;
            let __t228: ::routh::__private::f64 = __t15 * __t91;
            let __t230: ::routh::__private::f64 = __t228 - __v9;
            let __t231: ::routh::__private::f64 = __t55 * __t202;
            let __t233: ::routh::__private::f64 = __t230 + __t231;
            let __t235: ::routh::__private::f64 = __t26 + __t210;
            let __t236: ::routh::__private::f64 = __t29 + __t213;
            let __t237: ::routh::__private::f64 = __t15 + __t216;
            let __t238: ::routh::__private::f64 = __t90 * __t235;
            let __t239: ::routh::__private::f64 = __t90 * __t236;
            let __t240: ::routh::__private::f64 = __t90 * __t237;
            let __t241: ::routh::__private::f64 = __v7 * __t91;
            let __t242: ::routh::__private::f64 = __t141 * __t235;
            let __t244: ::routh::__private::f64 = __t241 - __t242;
            let __t245: ::routh::__private::f64 = __t141 * __t236;
            let __t246: ::routh::__private::f64 = -__t245;
            let __t247: ::routh::__private::f64 = __t141 * __t237;
            let __t248: ::routh::__private::f64 = -__t247;
            let __t249: ::routh::__private::f64 = __t142 * __t235;
            let __t250: ::routh::__private::f64 = -__t249;
            let __t251: ::routh::__private::f64 = __t142 * __t236;
            let __t253: ::routh::__private::f64 = __t241 - __t251;
            let __t254: ::routh::__private::f64 = __t142 * __t237;
            let __t255: ::routh::__private::f64 = -__t254;
            let __t256: ::routh::__private::f64 = __t143 * __t235;
            let __t257: ::routh::__private::f64 = -__t256;
            let __t258: ::routh::__private::f64 = __t143 * __t236;
            let __t259: ::routh::__private::f64 = -__t258;
            let __t260: ::routh::__private::f64 = __v8 * __t91;
            let __t261: ::routh::__private::f64 = __t143 * __t237;
            let __t263: ::routh::__private::f64 = __t260 - __t261;
            let __t264: ::routh::__private::f64 = __v7 * __t202;
            let __t265: ::routh::__private::f64 = __t235 * __t238;
            let __t267: ::routh::__private::f64 = __t264 - __t265;
            let __t268: ::routh::__private::f64 = __t236 * __t238;
            let __t269: ::routh::__private::f64 = -__t268;
            let __t270: ::routh::__private::f64 = __t237 * __t238;
            let __t271: ::routh::__private::f64 = -__t270;
            let __t272: ::routh::__private::f64 = __t236 * __t239;
            let __t274: ::routh::__private::f64 = __t264 - __t272;
            let __t275: ::routh::__private::f64 = __t237 * __t239;
            let __t276: ::routh::__private::f64 = -__t275;
            let __t277: ::routh::__private::f64 = __v8 * __t202;
            let __t278: ::routh::__private::f64 = __t237 * __t240;
            let __t280: ::routh::__private::f64 = __t277 - __t278;
            let __t281: ::routh::__private::f64 = -__t91;
            ::routh::__private::RouthBundle {
                routhian: __t96,
                psi_dot: __t91,
                dr_domega: ::routh::__private::Vector3::new(__t211, __t214, __t217),
                dr_dgamma: ::routh::__private::Vector3::new(__t222, __t227, __t233),
                dr_dp: __t281,
                d2r_domega2: ::routh::__private::Matrix3::new(
                    __t149,
                    __t151,
                    __t153,
                    __t151,
                    __t164,
                    __t166,
                    __t153,
                    __t166,
                    __t176,
                ),
                d2r_domega_dgamma: ::routh::__private::Matrix3::new(
                    __t244,
                    __t246,
                    __t248,
                    __t250,
                    __t253,
                    __t255,
                    __t257,
                    __t259,
                    __t263,
                ),
                d2r_dgamma2: ::routh::__private::Matrix3::new(
                    __t267,
                    __t269,
                    __t271,
                    __t269,
                    __t274,
                    __t276,
                    __t271,
                    __t276,
                    __t280,
                ),
            }
        }
        #[inline]
        fn gyroscopic_system(
            &self,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::GyroscopicSystem {
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t55: ::routh::__private::f64 = __v5 * __v8;
            let __t80: ::routh::__private::f64 = __v3 * __v3;
            let __t81: ::routh::__private::f64 = __v4 * __v4;
            let __t82: ::routh::__private::f64 = __t80 + __t81;
            let __t83: ::routh::__private::f64 = __v7 * __t82;
            let __t84: ::routh::__private::f64 = __v5 * __t55;
            let __t85: ::routh::__private::f64 = __t83 + __t84;
            let __t90: ::routh::__private::f64 = 1.0f64 / __t85;
            let __t106: ::routh::__private::f64 = __v3 * __v7;
            let __t112: ::routh::__private::f64 = __v4 * __v7;
            let __t141: ::routh::__private::f64 = __t90 * __t106;
            let __t142: ::routh::__private::f64 = __t90 * __t112;
            let __t143: ::routh::__private::f64 = __t55 * __t90;
            let __t147: ::routh::__private::f64 = __t106 * __t141;
            let __t149: ::routh::__private::f64 = __v7 - __t147;
            let __t150: ::routh::__private::f64 = __t112 * __t141;
            let __t151: ::routh::__private::f64 = -__t150;
            let __t152: ::routh::__private::f64 = __t55 * __t141;
            let __t153: ::routh::__private::f64 = -__t152;
            let __t162: ::routh::__private::f64 = __t112 * __t142;
            let __t164: ::routh::__private::f64 = __v7 - __t162;
            let __t165: ::routh::__private::f64 = __t55 * __t142;
            let __t166: ::routh::__private::f64 = -__t165;
            let __t174: ::routh::__private::f64 = __t55 * __t143;
            let __t176: ::routh::__private::f64 = __v8 - __t174;
            let __t304: ::routh::__private::f64 = __v6 * __t90;
            let __t378: ::routh::__private::f64 = __t304 * __t304;
            let __t382: ::routh::__private::f64 = __t106 * __t304;
            let __t384: ::routh::__private::f64 = __t112 * __t304;
            let __t386: ::routh::__private::f64 = __t55 * __t304;
            let __t388: ::routh::__private::f64 = __t106 * __t378;
            let __t390: ::routh::__private::f64 = __t112 * __t378;
            let __t392: ::routh::__private::f64 = __t55 * __t378;
            let __t394: ::routh::__private::f64 = __t392 - __v9;
            let __t396: ::routh::__private::f64 = __t90 * __t382;
            let __t398: ::routh::__private::f64 = __t90 * __t384;
            let __t400: ::routh::__private::f64 = __t90 * __t386;
            let __t402: ::routh::__private::f64 = __v7 * __t304;
            let __t403: ::routh::__private::f64 = __t141 * __t382;
            let __t405: ::routh::__private::f64 = (-2f64) * __t403;
            let __t406: ::routh::__private::f64 = __t402 + __t405;
            let __t407: ::routh::__private::f64 = __t141 * __t384;
            let __t410: ::routh::__private::f64 = __t141 * __t386;
            let __t413: ::routh::__private::f64 = __t142 * __t382;
            let __t416: ::routh::__private::f64 = __t142 * __t384;
            let __t418: ::routh::__private::f64 = (-2f64) * __t416;
            let __t419: ::routh::__private::f64 = __t402 + __t418;
            let __t420: ::routh::__private::f64 = __t142 * __t386;
            let __t423: ::routh::__private::f64 = __t143 * __t382;
            let __t426: ::routh::__private::f64 = __t143 * __t384;
            let __t429: ::routh::__private::f64 = __v8 * __t304;
            let __t430: ::routh::__private::f64 = __t143 * __t386;
            let __t432: ::routh::__private::f64 = (-2f64) * __t430;
            let __t433: ::routh::__private::f64 = __t429 + __t432;
            let __t434: ::routh::__private::f64 = __v7 * __t378;
            let __t435: ::routh::__private::f64 = __t382 * __t396;
            let __t438: ::routh::__private::f64 = (-4f64) * __t435;
            let __t439: ::routh::__private::f64 = __t434 + __t438;
            let __t440: ::routh::__private::f64 = __t384 * __t396;
            let __t444: ::routh::__private::f64 = __t386 * __t396;
            let __t448: ::routh::__private::f64 = __t384 * __t398;
            let __t451: ::routh::__private::f64 = (-4f64) * __t448;
            let __t452: ::routh::__private::f64 = __t434 + __t451;
            let __t453: ::routh::__private::f64 = __t386 * __t398;
            let __t457: ::routh::__private::f64 = __v8 * __t378;
            let __t458: ::routh::__private::f64 = __t386 * __t400;
            let __t461: ::routh::__private::f64 = (-4f64) * __t458;
            let __t462: ::routh::__private::f64 = __t457 + __t461;
            let __t470: ::routh::__private::f64 = __v5 * __t407;
            let __t471: ::routh::__private::f64 = (-2f64) * __t470;
            let __t472: ::routh::__private::f64 = __v4 * __t410;
            let __t473: ::routh::__private::f64 = (-2f64) * __t472;
            let __t474: ::routh::__private::f64 = 2f64 * __t472;
            let __t475: ::routh::__private::f64 = __t471 + __t474;
            let __t476: ::routh::__private::f64 = __v5 * __t406;
            let __t478: ::routh::__private::f64 = __v3 * __t410;
            let __t479: ::routh::__private::f64 = (-2f64) * __t478;
            let __t480: ::routh::__private::f64 = __t479 - __t476;
            let __t481: ::routh::__private::f64 = __v4 * __t406;
            let __t482: ::routh::__private::f64 = __v3 * __t407;
            let __t483: ::routh::__private::f64 = (-2f64) * __t482;
            let __t484: ::routh::__private::f64 = 2f64 * __t482;
            let __t485: ::routh::__private::f64 = __t481 + __t484;
            let __t486: ::routh::__private::f64 = __v5 * __t419;
            let __t487: ::routh::__private::f64 = __v4 * __t420;
            let __t488: ::routh::__private::f64 = (-2f64) * __t487;
            let __t489: ::routh::__private::f64 = 2f64 * __t487;
            let __t490: ::routh::__private::f64 = __t486 + __t489;
            let __t491: ::routh::__private::f64 = __v5 * __t413;
            let __t492: ::routh::__private::f64 = (-2f64) * __t491;
            let __t493: ::routh::__private::f64 = 2f64 * __t491;
            let __t494: ::routh::__private::f64 = __v3 * __t420;
            let __t495: ::routh::__private::f64 = (-2f64) * __t494;
            let __t496: ::routh::__private::f64 = __t493 + __t495;
            let __t497: ::routh::__private::f64 = __v4 * __t413;
            let __t498: ::routh::__private::f64 = (-2f64) * __t497;
            let __t499: ::routh::__private::f64 = __v3 * __t419;
            let __t501: ::routh::__private::f64 = __t498 - __t499;
            let __t502: ::routh::__private::f64 = __v5 * __t426;
            let __t503: ::routh::__private::f64 = (-2f64) * __t502;
            let __t504: ::routh::__private::f64 = __v4 * __t433;
            let __t506: ::routh::__private::f64 = __t503 - __t504;
            let __t507: ::routh::__private::f64 = __v5 * __t423;
            let __t508: ::routh::__private::f64 = (-2f64) * __t507;
            let __t509: ::routh::__private::f64 = 2f64 * __t507;
            let __t510: ::routh::__private::f64 = __v3 * __t433;
            let __t511: ::routh::__private::f64 = __t509 + __t510;
            let __t512: ::routh::__private::f64 = __v4 * __t423;
            let __t513: ::routh::__private::f64 = (-2f64) * __t512;
            let __t514: ::routh::__private::f64 = __v3 * __t426;
            let __t515: ::routh::__private::f64 = (-2f64) * __t514;
            let __t516: ::routh::__private::f64 = 2f64 * __t514;
            let __t517: ::routh::__private::f64 = __t513 + __t516;
            let __t518: ::routh::__private::f64 = 2f64 * __t470;
            let __t519: ::routh::__private::f64 = __t473 + __t518;
            let __t521: ::routh::__private::f64 = __t488 - __t486;
            let __t522: ::routh::__private::f64 = 2f64 * __t502;
            let __t523: ::routh::__private::f64 = __t504 + __t522;
            let __t524: ::routh::__private::f64 = 2f64 * __t478;
            let __t525: ::routh::__private::f64 = __t476 + __t524;
            let __t526: ::routh::__private::f64 = 2f64 * __t494;
            let __t527: ::routh::__private::f64 = __t492 + __t526;
            let __t529: ::routh::__private::f64 = __t508 - __t510;
            let __t531: ::routh::__private::f64 = __t483 - __t481;
            let __t532: ::routh::__private::f64 = 2f64 * __t497;
            let __t533: ::routh::__private::f64 = __t499 + __t532;
            let __t534: ::routh::__private::f64 = 2f64 * __t512;
            let __t535: ::routh::__private::f64 = __t515 + __t534;
            let __t536: ::routh::__private::f64 = __t475 + __t519;
            let __t537: ::routh::__private::f64 = 0.5f64 * __t536;
            let __t538: ::routh::__private::f64 = __t480 + __t521;
            let __t539: ::routh::__private::f64 = __t386 + __t538;
            let __t540: ::routh::__private::f64 = 0.5f64 * __t539;
            let __t541: ::routh::__private::f64 = __t485 + __t523;
            let __t542: ::routh::__private::f64 = __t541 - __t384;
            let __t543: ::routh::__private::f64 = 0.5f64 * __t542;
            let __t544: ::routh::__private::f64 = __t490 + __t525;
            let __t545: ::routh::__private::f64 = __t544 - __t386;
            let __t546: ::routh::__private::f64 = 0.5f64 * __t545;
            let __t547: ::routh::__private::f64 = __t496 + __t527;
            let __t548: ::routh::__private::f64 = 0.5f64 * __t547;
            let __t549: ::routh::__private::f64 = __t501 + __t529;
            let __t550: ::routh::__private::f64 = __t382 + __t549;
            let __t551: ::routh::__private::f64 = 0.5f64 * __t550;
            let __t552: ::routh::__private::f64 = __t506 + __t531;
            let __t553: ::routh::__private::f64 = __t384 + __t552;
            let __t554: ::routh::__private::f64 = 0.5f64 * __t553;
            let __t555: ::routh::__private::f64 = __t511 + __t533;
            let __t556: ::routh::__private::f64 = __t555 - __t382;
            let __t557: ::routh::__private::f64 = 0.5f64 * __t556;
            let __t558: ::routh::__private::f64 = __t517 + __t535;
            let __t559: ::routh::__private::f64 = 0.5f64 * __t558;
            let __t560: ::routh::__private::f64 = __v3 * __t388;
            let __t561: ::routh::__private::f64 = __v4 * __t390;
            let __t562: ::routh::__private::f64 = __v5 * __t394;
            let __t563: ::routh::__private::f64 = __t560 + __t561;
            let __t564: ::routh::__private::f64 = __t562 + __t563;
            let __t566: ::routh::__private::f64 = __t564 - __t439;
            let __t568: ::routh::__private::f64 = __t564 - __t452;
            let __t570: ::routh::__private::f64 = __t564 - __t462;
            let __t571: ::routh::__private::f64 = __v5 * __t440;
            let __t572: ::routh::__private::f64 = 4f64 * __t571;
            let __t573: ::routh::__private::f64 = __v4 * __t444;
            let __t574: ::routh::__private::f64 = 4f64 * __t573;
            let __t575: ::routh::__private::f64 = (-4f64) * __t573;
            let __t576: ::routh::__private::f64 = __t572 + __t575;
            let __t577: ::routh::__private::f64 = __v5 * __t568;
            let __t578: ::routh::__private::f64 = __v4 * __t453;
            let __t580: ::routh::__private::f64 = (-4f64) * __t578;
            let __t581: ::routh::__private::f64 = __t577 + __t580;
            let __t582: ::routh::__private::f64 = __v5 * __t453;
            let __t583: ::routh::__private::f64 = 4f64 * __t582;
            let __t584: ::routh::__private::f64 = __v4 * __t570;
            let __t586: ::routh::__private::f64 = __t583 - __t584;
            let __t587: ::routh::__private::f64 = __v5 * __t566;
            let __t589: ::routh::__private::f64 = __v3 * __t444;
            let __t590: ::routh::__private::f64 = 4f64 * __t589;
            let __t591: ::routh::__private::f64 = __t590 - __t587;
            let __t592: ::routh::__private::f64 = (-4f64) * __t571;
            let __t593: ::routh::__private::f64 = __v3 * __t453;
            let __t594: ::routh::__private::f64 = 4f64 * __t593;
            let __t595: ::routh::__private::f64 = __t592 + __t594;
            let __t596: ::routh::__private::f64 = __v5 * __t444;
            let __t598: ::routh::__private::f64 = (-4f64) * __t596;
            let __t599: ::routh::__private::f64 = __v3 * __t570;
            let __t600: ::routh::__private::f64 = __t598 + __t599;
            let __t601: ::routh::__private::f64 = __v4 * __t566;
            let __t602: ::routh::__private::f64 = __v3 * __t440;
            let __t604: ::routh::__private::f64 = (-4f64) * __t602;
            let __t605: ::routh::__private::f64 = __t601 + __t604;
            let __t606: ::routh::__private::f64 = __v4 * __t440;
            let __t607: ::routh::__private::f64 = 4f64 * __t606;
            let __t608: ::routh::__private::f64 = __v3 * __t568;
            let __t610: ::routh::__private::f64 = __t607 - __t608;
            let __t611: ::routh::__private::f64 = (-4f64) * __t593;
            let __t612: ::routh::__private::f64 = __t574 + __t611;
            let __t613: ::routh::__private::f64 = __v5 * __t581;
            let __t614: ::routh::__private::f64 = __v4 * __t586;
            let __t616: ::routh::__private::f64 = __t613 - __t614;
            let __t617: ::routh::__private::f64 = __v5 * __t576;
            let __t619: ::routh::__private::f64 = __v3 * __t586;
            let __t620: ::routh::__private::f64 = __t619 - __t617;
            let __t621: ::routh::__private::f64 = __v4 * __t576;
            let __t622: ::routh::__private::f64 = __v3 * __t581;
            let __t624: ::routh::__private::f64 = __t621 - __t622;
            let __t625: ::routh::__private::f64 = __v5 * __t595;
            let __t626: ::routh::__private::f64 = __v4 * __t600;
            let __t628: ::routh::__private::f64 = __t625 - __t626;
            let __t629: ::routh::__private::f64 = __v5 * __t591;
            let __t631: ::routh::__private::f64 = __v3 * __t600;
            let __t632: ::routh::__private::f64 = __t631 - __t629;
            let __t633: ::routh::__private::f64 = __v4 * __t591;
            let __t634: ::routh::__private::f64 = __v3 * __t595;
            let __t636: ::routh::__private::f64 = __t633 - __t634;
            let __t637: ::routh::__private::f64 = __v5 * __t610;
            let __t638: ::routh::__private::f64 = __v4 * __t612;
            let __t640: ::routh::__private::f64 = __t637 - __t638;
            let __t641: ::routh::__private::f64 = __v5 * __t605;
            let __t643: ::routh::__private::f64 = __v3 * __t612;
            let __t644: ::routh::__private::f64 = __t643 - __t641;
            let __t645: ::routh::__private::f64 = __v4 * __t605;
            let __t646: ::routh::__private::f64 = __v3 * __t610;
            let __t648: ::routh::__private::f64 = __t645 - __t646;
            ::routh::__private::GyroscopicSystem {
                a: ::routh::__private::Matrix3::new(
                    __t149,
                    __t151,
                    __t153,
                    __t151,
                    __t164,
                    __t166,
                    __t153,
                    __t166,
                    __t176,
                ),
                g: ::routh::__private::Matrix3::new(
                    __t537,
                    __t540,
                    __t543,
                    __t546,
                    __t548,
                    __t551,
                    __t554,
                    __t557,
                    __t559,
                ),
                c: ::routh::__private::Matrix3::new(
                    __t616,
                    __t620,
                    __t624,
                    __t628,
                    __t632,
                    __t636,
                    __t640,
                    __t644,
                    __t648,
                ),
            }
        }
    }
};
