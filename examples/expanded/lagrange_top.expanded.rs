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
            let __t19: ::routh::__private::f64 = __v5 * __v9;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t33: ::routh::__private::f64 = __v0 * __t26;
            let __t34: ::routh::__private::f64 = __v1 * __t29;
            let __t39: ::routh::__private::f64 = (-0.5f64) * __t14;
            let __t40: ::routh::__private::f64 = 0.5f64 * __t16;
            let __t41: ::routh::__private::f64 = __t39 + __t40;
            let __t42: ::routh::__private::f64 = __t19 + __t41;
            let __t43: ::routh::__private::f64 = __t33 + __t42;
            let __t44: ::routh::__private::f64 = __t34 + __t43;
            __t44
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
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t45: ::routh::__private::f64 = __v3 * __t26;
            let __t46: ::routh::__private::f64 = __v4 * __t29;
            let __t47: ::routh::__private::f64 = __v5 * __t15;
            let __t48: ::routh::__private::f64 = __t45 + __t46;
            let __t49: ::routh::__private::f64 = __t47 + __t48;
            __t49
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
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t45: ::routh::__private::f64 = __v3 * __t26;
            let __t46: ::routh::__private::f64 = __v4 * __t29;
            let __t47: ::routh::__private::f64 = __v5 * __t15;
            let __t48: ::routh::__private::f64 = __t45 + __t46;
            let __t49: ::routh::__private::f64 = __t47 + __t48;
            let __t50: ::routh::__private::f64 = __v3 * __v3;
            let __t51: ::routh::__private::f64 = __v4 * __v4;
            let __t52: ::routh::__private::f64 = __t50 + __t51;
            let __t53: ::routh::__private::f64 = __v7 * __t52;
            let __t54: ::routh::__private::f64 = __v5 * __v8;
            let __t55: ::routh::__private::f64 = __v5 * __t54;
            let __t56: ::routh::__private::f64 = __t53 + __t55;
            let __t59: ::routh::__private::f64 = __v6 - __t49;
            let __t61: ::routh::__private::f64 = __t59 / __t56;
            __t61
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
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t45: ::routh::__private::f64 = __v3 * __t26;
            let __t46: ::routh::__private::f64 = __v4 * __t29;
            let __t47: ::routh::__private::f64 = __v5 * __t15;
            let __t48: ::routh::__private::f64 = __t45 + __t46;
            let __t49: ::routh::__private::f64 = __t47 + __t48;
            let __t50: ::routh::__private::f64 = __v3 * __v3;
            let __t51: ::routh::__private::f64 = __v4 * __v4;
            let __t52: ::routh::__private::f64 = __t50 + __t51;
            let __t53: ::routh::__private::f64 = __v7 * __t52;
            let __t54: ::routh::__private::f64 = __v5 * __v8;
            let __t55: ::routh::__private::f64 = __v5 * __t54;
            let __t56: ::routh::__private::f64 = __t53 + __t55;
            let __t59: ::routh::__private::f64 = __v6 - __t49;
            let __t61: ::routh::__private::f64 = __t59 / __t56;
            let __t63: ::routh::__private::f64 = __t59 * __t61;
            let __t65: ::routh::__private::f64 = (-0.5f64) * __t63;
            let __t66: ::routh::__private::f64 = __t22 + __t65;
            __t66
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
            let __t45: ::routh::__private::f64 = __v3 * __t26;
            let __t46: ::routh::__private::f64 = __v4 * __t29;
            let __t47: ::routh::__private::f64 = __v5 * __t15;
            let __t48: ::routh::__private::f64 = __t45 + __t46;
            let __t49: ::routh::__private::f64 = __t47 + __t48;
            let __t50: ::routh::__private::f64 = __v3 * __v3;
            let __t51: ::routh::__private::f64 = __v4 * __v4;
            let __t52: ::routh::__private::f64 = __t50 + __t51;
            let __t53: ::routh::__private::f64 = __v7 * __t52;
            let __t54: ::routh::__private::f64 = __v5 * __v8;
            let __t55: ::routh::__private::f64 = __v5 * __t54;
            let __t56: ::routh::__private::f64 = __t53 + __t55;
            let __t59: ::routh::__private::f64 = __v6 - __t49;
            let __t61: ::routh::__private::f64 = __t59 / __t56;
            let __t74: ::routh::__private::f64 = __v3 * __v7;
            let __t77: ::routh::__private::f64 = __v4 * __v7;
            let __t174: ::routh::__private::f64 = __t61 * __t74;
            let __t175: ::routh::__private::f64 = __t26 + __t174;
            let __t176: ::routh::__private::f64 = __t61 * __t77;
            let __t177: ::routh::__private::f64 = __t29 + __t176;
            let __t178: ::routh::__private::f64 = __t54 * __t61;
            let __t179: ::routh::__private::f64 = __t15 + __t178;
            ::routh::__private::Vector3::new(__t175, __t177, __t179)
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
            let __t45: ::routh::__private::f64 = __v3 * __t26;
            let __t46: ::routh::__private::f64 = __v4 * __t29;
            let __t47: ::routh::__private::f64 = __v5 * __t15;
            let __t48: ::routh::__private::f64 = __t45 + __t46;
            let __t49: ::routh::__private::f64 = __t47 + __t48;
            let __t50: ::routh::__private::f64 = __v3 * __v3;
            let __t51: ::routh::__private::f64 = __v4 * __v4;
            let __t52: ::routh::__private::f64 = __t50 + __t51;
            let __t53: ::routh::__private::f64 = __v7 * __t52;
            let __t54: ::routh::__private::f64 = __v5 * __v8;
            let __t55: ::routh::__private::f64 = __v5 * __t54;
            let __t56: ::routh::__private::f64 = __t53 + __t55;
            let __t59: ::routh::__private::f64 = __v6 - __t49;
            let __t61: ::routh::__private::f64 = __t59 / __t56;
            let __t74: ::routh::__private::f64 = __v3 * __v7;
            let __t77: ::routh::__private::f64 = __v4 * __v7;
            let __t168: ::routh::__private::f64 = __t61 * __t61;
            let __t180: ::routh::__private::f64 = __t26 * __t61;
            let __t181: ::routh::__private::f64 = __t74 * __t168;
            let __t183: ::routh::__private::f64 = __t180 + __t181;
            let __t184: ::routh::__private::f64 = __t29 * __t61;
            let __t185: ::routh::__private::f64 = __t77 * __t168;
            let __t187: ::routh::__private::f64 = __t184 + __t185;
            let __t188: ::routh::__private::f64 = __t15 * __t61;
            let __t189: ::routh::__private::f64 = __t188 - __v9;
            let __t190: ::routh::__private::f64 = __t54 * __t168;
            let __t192: ::routh::__private::f64 = __t189 + __t190;
            ::routh::__private::Vector3::new(__t183, __t187, __t192)
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
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t45: ::routh::__private::f64 = __v3 * __t26;
            let __t46: ::routh::__private::f64 = __v4 * __t29;
            let __t47: ::routh::__private::f64 = __v5 * __t15;
            let __t48: ::routh::__private::f64 = __t45 + __t46;
            let __t49: ::routh::__private::f64 = __t47 + __t48;
            let __t50: ::routh::__private::f64 = __v3 * __v3;
            let __t51: ::routh::__private::f64 = __v4 * __v4;
            let __t52: ::routh::__private::f64 = __t50 + __t51;
            let __t53: ::routh::__private::f64 = __v7 * __t52;
            let __t54: ::routh::__private::f64 = __v5 * __v8;
            let __t55: ::routh::__private::f64 = __v5 * __t54;
            let __t56: ::routh::__private::f64 = __t53 + __t55;
            let __t59: ::routh::__private::f64 = __v6 - __t49;
            let __t61: ::routh::__private::f64 = __t59 / __t56;
            let __t243: ::routh::__private::f64 = -__t61;
            __t243
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
            let __t50: ::routh::__private::f64 = __v3 * __v3;
            let __t51: ::routh::__private::f64 = __v4 * __v4;
            let __t52: ::routh::__private::f64 = __t50 + __t51;
            let __t53: ::routh::__private::f64 = __v7 * __t52;
            let __t54: ::routh::__private::f64 = __v5 * __v8;
            let __t55: ::routh::__private::f64 = __v5 * __t54;
            let __t56: ::routh::__private::f64 = __t53 + __t55;
            let __t60: ::routh::__private::f64 = 1.0f64 / __t56;
            let __t74: ::routh::__private::f64 = __v3 * __v7;
            let __t77: ::routh::__private::f64 = __v4 * __v7;
            let __t107: ::routh::__private::f64 = __t60 * __t74;
            let __t108: ::routh::__private::f64 = __t60 * __t77;
            let __t109: ::routh::__private::f64 = __t54 * __t60;
            let __t113: ::routh::__private::f64 = __t74 * __t107;
            let __t115: ::routh::__private::f64 = __v7 - __t113;
            let __t116: ::routh::__private::f64 = __t77 * __t107;
            let __t117: ::routh::__private::f64 = -__t116;
            let __t118: ::routh::__private::f64 = __t54 * __t107;
            let __t119: ::routh::__private::f64 = -__t118;
            let __t128: ::routh::__private::f64 = __t77 * __t108;
            let __t130: ::routh::__private::f64 = __v7 - __t128;
            let __t131: ::routh::__private::f64 = __t54 * __t108;
            let __t132: ::routh::__private::f64 = -__t131;
            let __t140: ::routh::__private::f64 = __t54 * __t109;
            let __t142: ::routh::__private::f64 = __v8 - __t140;
            ::routh::__private::Matrix3::new(
                __t115,
                __t117,
                __t119,
                __t117,
                __t130,
                __t132,
                __t119,
                __t132,
                __t142,
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
            let __t45: ::routh::__private::f64 = __v3 * __t26;
            let __t46: ::routh::__private::f64 = __v4 * __t29;
            let __t47: ::routh::__private::f64 = __v5 * __t15;
            let __t48: ::routh::__private::f64 = __t45 + __t46;
            let __t49: ::routh::__private::f64 = __t47 + __t48;
            let __t50: ::routh::__private::f64 = __v3 * __v3;
            let __t51: ::routh::__private::f64 = __v4 * __v4;
            let __t52: ::routh::__private::f64 = __t50 + __t51;
            let __t53: ::routh::__private::f64 = __v7 * __t52;
            let __t54: ::routh::__private::f64 = __v5 * __v8;
            let __t55: ::routh::__private::f64 = __v5 * __t54;
            let __t56: ::routh::__private::f64 = __t53 + __t55;
            let __t59: ::routh::__private::f64 = __v6 - __t49;
            let __t60: ::routh::__private::f64 = 1.0f64 / __t56;
            let __t61: ::routh::__private::f64 = __t59 * __t60;
            let __t74: ::routh::__private::f64 = __v3 * __v7;
            let __t77: ::routh::__private::f64 = __v4 * __v7;
            let __t107: ::routh::__private::f64 = __t60 * __t74;
            let __t108: ::routh::__private::f64 = __t60 * __t77;
            let __t109: ::routh::__private::f64 = __t54 * __t60;
            let __t174: ::routh::__private::f64 = __t61 * __t74;
            let __t176: ::routh::__private::f64 = __t61 * __t77;
            let __t178: ::routh::__private::f64 = __t54 * __t61;
            let __t194: ::routh::__private::f64 = 2f64 * __t174;
            let __t195: ::routh::__private::f64 = __t26 + __t194;
            let __t196: ::routh::__private::f64 = 2f64 * __t176;
            let __t197: ::routh::__private::f64 = __t29 + __t196;
            let __t198: ::routh::__private::f64 = 2f64 * __t178;
            let __t199: ::routh::__private::f64 = __t15 + __t198;
            let __t203: ::routh::__private::f64 = __v7 * __t61;
            let __t204: ::routh::__private::f64 = __t107 * __t195;
            let __t206: ::routh::__private::f64 = __t203 - __t204;
            let __t207: ::routh::__private::f64 = __t107 * __t197;
            let __t208: ::routh::__private::f64 = -__t207;
            let __t209: ::routh::__private::f64 = __t107 * __t199;
            let __t210: ::routh::__private::f64 = -__t209;
            let __t211: ::routh::__private::f64 = __t108 * __t195;
            let __t212: ::routh::__private::f64 = -__t211;
            let __t213: ::routh::__private::f64 = __t108 * __t197;
            let __t215: ::routh::__private::f64 = __t203 - __t213;
            let __t216: ::routh::__private::f64 = __t108 * __t199;
            let __t217: ::routh::__private::f64 = -__t216;
            let __t218: ::routh::__private::f64 = __t109 * __t195;
            let __t219: ::routh::__private::f64 = -__t218;
            let __t220: ::routh::__private::f64 = __t109 * __t197;
            let __t221: ::routh::__private::f64 = -__t220;
            let __t222: ::routh::__private::f64 = __v8 * __t61;
            let __t223: ::routh::__private::f64 = __t109 * __t199;
            let __t225: ::routh::__private::f64 = __t222 - __t223;
            ::routh::__private::Matrix3::new(
                __t206,
                __t208,
                __t210,
                __t212,
                __t215,
                __t217,
                __t219,
                __t221,
                __t225,
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
            let __t45: ::routh::__private::f64 = __v3 * __t26;
            let __t46: ::routh::__private::f64 = __v4 * __t29;
            let __t47: ::routh::__private::f64 = __v5 * __t15;
            let __t48: ::routh::__private::f64 = __t45 + __t46;
            let __t49: ::routh::__private::f64 = __t47 + __t48;
            let __t50: ::routh::__private::f64 = __v3 * __v3;
            let __t51: ::routh::__private::f64 = __v4 * __v4;
            let __t52: ::routh::__private::f64 = __t50 + __t51;
            let __t53: ::routh::__private::f64 = __v7 * __t52;
            let __t54: ::routh::__private::f64 = __v5 * __v8;
            let __t55: ::routh::__private::f64 = __v5 * __t54;
            let __t56: ::routh::__private::f64 = __t53 + __t55;
            let __t59: ::routh::__private::f64 = __v6 - __t49;
            let __t60: ::routh::__private::f64 = 1.0f64 / __t56;
            let __t61: ::routh::__private::f64 = __t59 * __t60;
            let __t74: ::routh::__private::f64 = __v3 * __v7;
            let __t77: ::routh::__private::f64 = __v4 * __v7;
            let __t168: ::routh::__private::f64 = __t61 * __t61;
            let __t174: ::routh::__private::f64 = __t61 * __t74;
            let __t176: ::routh::__private::f64 = __t61 * __t77;
            let __t178: ::routh::__private::f64 = __t54 * __t61;
            let __t194: ::routh::__private::f64 = 2f64 * __t174;
            let __t195: ::routh::__private::f64 = __t26 + __t194;
            let __t196: ::routh::__private::f64 = 2f64 * __t176;
            let __t197: ::routh::__private::f64 = __t29 + __t196;
            let __t198: ::routh::__private::f64 = 2f64 * __t178;
            let __t199: ::routh::__private::f64 = __t15 + __t198;
            let __t200: ::routh::__private::f64 = __t60 * __t195;
            let __t201: ::routh::__private::f64 = __t60 * __t197;
            let __t202: ::routh::__private::f64 = __t60 * __t199;
            let __t226: ::routh::__private::f64 = __v7 * __t168;
            let __t227: ::routh::__private::f64 = __t195 * __t200;
            let __t229: ::routh::__private::f64 = __t226 - __t227;
            let __t230: ::routh::__private::f64 = __t197 * __t200;
            let __t231: ::routh::__private::f64 = -__t230;
            let __t232: ::routh::__private::f64 = __t199 * __t200;
            let __t233: ::routh::__private::f64 = -__t232;
            let __t234: ::routh::__private::f64 = __t197 * __t201;
            let __t236: ::routh::__private::f64 = __t226 - __t234;
            let __t237: ::routh::__private::f64 = __t199 * __t201;
            let __t238: ::routh::__private::f64 = -__t237;
            let __t239: ::routh::__private::f64 = __v8 * __t168;
            let __t240: ::routh::__private::f64 = __t199 * __t202;
            let __t242: ::routh::__private::f64 = __t239 - __t240;
            ::routh::__private::Matrix3::new(
                __t229,
                __t231,
                __t233,
                __t231,
                __t236,
                __t238,
                __t233,
                __t238,
                __t242,
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
            let __t50: ::routh::__private::f64 = __v3 * __v3;
            let __t51: ::routh::__private::f64 = __v4 * __v4;
            let __t52: ::routh::__private::f64 = __t50 + __t51;
            let __t53: ::routh::__private::f64 = __v7 * __t52;
            let __t54: ::routh::__private::f64 = __v5 * __v8;
            let __t55: ::routh::__private::f64 = __v5 * __t54;
            let __t56: ::routh::__private::f64 = __t53 + __t55;
            let __t244: ::routh::__private::f64 = __v6 / __t56;
            let __t246: ::routh::__private::f64 = __v6 * __t244;
            let __t248: ::routh::__private::f64 = (-0.5f64) * __t246;
            let __t249: ::routh::__private::f64 = __t248 - __t19;
            let __t403: ::routh::__private::f64 = -__t249;
            __t403
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
            let __t45: ::routh::__private::f64 = __v3 * __t26;
            let __t46: ::routh::__private::f64 = __v4 * __t29;
            let __t47: ::routh::__private::f64 = __v5 * __t15;
            let __t48: ::routh::__private::f64 = __t45 + __t46;
            let __t49: ::routh::__private::f64 = __t47 + __t48;
            let __t50: ::routh::__private::f64 = __v3 * __v3;
            let __t51: ::routh::__private::f64 = __v4 * __v4;
            let __t52: ::routh::__private::f64 = __t50 + __t51;
            let __t53: ::routh::__private::f64 = __v7 * __t52;
            let __t54: ::routh::__private::f64 = __v5 * __v8;
            let __t55: ::routh::__private::f64 = __v5 * __t54;
            let __t56: ::routh::__private::f64 = __t53 + __t55;
            let __t59: ::routh::__private::f64 = __v6 - __t49;
            let __t60: ::routh::__private::f64 = 1.0f64 / __t56;
            let __t61: ::routh::__private::f64 = __t59 * __t60;
            let __t63: ::routh::__private::f64 = __t59 * __t61;
            let __t65: ::routh::__private::f64 = (-0.5f64) * __t63;
            let __t66: ::routh::__private::f64 = __t22 + __t65;
            let __t74: ::routh::__private::f64 = __v3 * __v7;
            let __t77: ::routh::__private::f64 = __v4 * __v7;
            let __t107: ::routh::__private::f64 = __t60 * __t74;
            let __t108: ::routh::__private::f64 = __t60 * __t77;
            let __t109: ::routh::__private::f64 = __t54 * __t60;
            let __t113: ::routh::__private::f64 = __t74 * __t107;
            let __t115: ::routh::__private::f64 = __v7 - __t113;
            let __t116: ::routh::__private::f64 = __t77 * __t107;
            let __t117: ::routh::__private::f64 = -__t116;
            let __t118: ::routh::__private::f64 = __t54 * __t107;
            let __t119: ::routh::__private::f64 = -__t118;
            let __t128: ::routh::__private::f64 = __t77 * __t108;
            let __t130: ::routh::__private::f64 = __v7 - __t128;
            let __t131: ::routh::__private::f64 = __t54 * __t108;
            let __t132: ::routh::__private::f64 = -__t131;
            let __t140: ::routh::__private::f64 = __t54 * __t109;
            let __t142: ::routh::__private::f64 = __v8 - __t140;
            let __t168: ::routh::__private::f64 = __t61 * __t61;
            let __t174: ::routh::__private::f64 = __t61 * __t74;
            let __t175: ::routh::__private::f64 = __t26 + __t174;
            let __t176: ::routh::__private::f64 = __t61 * __t77;
            let __t177: ::routh::__private::f64 = __t29 + __t176;
            let __t178: ::routh::__private::f64 = __t54 * __t61;
            let __t179: ::routh::__private::f64 = __t15 + __t178;
            let __t180: ::routh::__private::f64 = __t26 * __t61;
            let __t181: ::routh::__private::f64 = __t74 * __t168;
            let __t183: ::routh::__private::f64 = __t180 + __t181;
            let __t184: ::routh::__private::f64 = __t29 * __t61;
            let __t185: ::routh::__private::f64 = __t77 * __t168;
            let __t187: ::routh::__private::f64 = __t184 + __t185;
            let __t188: ::routh::__private::f64 = __t15 * __t61;
            let __t189: ::routh::__private::f64 = __t188 - __v9;
            let __t190: ::routh::__private::f64 = __t54 * __t168;
            let __t192: ::routh::__private::f64 = __t189 + __t190;
            let __t194: ::routh::__private::f64 = 2f64 * __t174;
            let __t195: ::routh::__private::f64 = __t26 + __t194;
            let __t196: ::routh::__private::f64 = 2f64 * __t176;
            let __t197: ::routh::__private::f64 = __t29 + __t196;
            let __t198: ::routh::__private::f64 = 2f64 * __t178;
            let __t199: ::routh::__private::f64 = __t15 + __t198;
            let __t200: ::routh::__private::f64 = __t60 * __t195;
            let __t201: ::routh::__private::f64 = __t60 * __t197;
            let __t202: ::routh::__private::f64 = __t60 * __t199;
            let __t203: ::routh::__private::f64 = __v7 * __t61;
            let __t204: ::routh::__private::f64 = __t107 * __t195;
            let __t206: ::routh::__private::f64 = __t203 - __t204;
            let __t207: ::routh::__private::f64 = __t107 * __t197;
            let __t208: ::routh::__private::f64 = -__t207;
            let __t209: ::routh::__private::f64 = __t107 * __t199;
            let __t210: ::routh::__private::f64 = -__t209;
            let __t211: ::routh::__private::f64 = __t108 * __t195;
            let __t212: ::routh::__private::f64 = -__t211;
            let __t213: ::routh::__private::f64 = __t108 * __t197;
            let __t215: ::routh::__private::f64 = __t203 - __t213;
            let __t216: ::routh::__private::f64 = __t108 * __t199;
            let __t217: ::routh::__private::f64 = -__t216;
            let __t218: ::routh::__private::f64 = __t109 * __t195;
            let __t219: ::routh::__private::f64 = -__t218;
            let __t220: ::routh::__private::f64 = __t109 * __t197;
            let __t221: ::routh::__private::f64 = -__t220;
            let __t222: ::routh::__private::f64 = __v8 * __t61;
            let __t223: ::routh::__private::f64 = __t109 * __t199;
            let __t225: ::routh::__private::f64 = __t222 - __t223;
            let __t226: ::routh::__private::f64 = __v7 * __t168;
            let __t227: ::routh::__private::f64 = __t195 * __t200;
            let __t229: ::routh::__private::f64 = __t226 - __t227;
            let __t230: ::routh::__private::f64 = __t197 * __t200;
            let __t231: ::routh::__private::f64 = -__t230;
            let __t232: ::routh::__private::f64 = __t199 * __t200;
            let __t233: ::routh::__private::f64 = -__t232;
            let __t234: ::routh::__private::f64 = __t197 * __t201;
            let __t236: ::routh::__private::f64 = __t226 - __t234;
            let __t237: ::routh::__private::f64 = __t199 * __t201;
            let __t238: ::routh::__private::f64 = -__t237;
            let __t239: ::routh::__private::f64 = __v8 * __t168;
            let __t240: ::routh::__private::f64 = __t199 * __t202;
            let __t242: ::routh::__private::f64 = __t239 - __t240;
            let __t243: ::routh::__private::f64 = -__t61;
            ::routh::__private::RouthBundle {
                routhian: __t66,
                psi_dot: __t61,
                dr_domega: ::routh::__private::Vector3::new(__t175, __t177, __t179),
                dr_dgamma: ::routh::__private::Vector3::new(__t183, __t187, __t192),
                dr_dp: __t243,
                d2r_domega2: ::routh::__private::Matrix3::new(
                    __t115,
                    __t117,
                    __t119,
                    __t117,
                    __t130,
                    __t132,
                    __t119,
                    __t132,
                    __t142,
                ),
                d2r_domega_dgamma: ::routh::__private::Matrix3::new(
                    __t206,
                    __t208,
                    __t210,
                    __t212,
                    __t215,
                    __t217,
                    __t219,
                    __t221,
                    __t225,
                ),
                d2r_dgamma2: ::routh::__private::Matrix3::new(
                    __t229,
                    __t231,
                    __t233,
                    __t231,
                    __t236,
                    __t238,
                    __t233,
                    __t238,
                    __t242,
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
            let __t50: ::routh::__private::f64 = __v3 * __v3;
            let __t51: ::routh::__private::f64 = __v4 * __v4;
            let __t52: ::routh::__private::f64 = __t50 + __t51;
            let __t53: ::routh::__private::f64 = __v7 * __t52;
            let __t54: ::routh::__private::f64 = __v5 * __v8;
            let __t55: ::routh::__private::f64 = __v5 * __t54;
            let __t56: ::routh::__private::f64 = __t53 + __t55;
            let __t60: ::routh::__private::f64 = 1.0f64 / __t56;
            let __t74: ::routh::__private::f64 = __v3 * __v7;
            let __t77: ::routh::__private::f64 = __v4 * __v7;
            let __t107: ::routh::__private::f64 = __t60 * __t74;
            let __t108: ::routh::__private::f64 = __t60 * __t77;
            let __t109: ::routh::__private::f64 = __t54 * __t60;
            let __t113: ::routh::__private::f64 = __t74 * __t107;
            let __t115: ::routh::__private::f64 = __v7 - __t113;
            let __t116: ::routh::__private::f64 = __t77 * __t107;
            let __t117: ::routh::__private::f64 = -__t116;
            let __t118: ::routh::__private::f64 = __t54 * __t107;
            let __t119: ::routh::__private::f64 = -__t118;
            let __t128: ::routh::__private::f64 = __t77 * __t108;
            let __t130: ::routh::__private::f64 = __v7 - __t128;
            let __t131: ::routh::__private::f64 = __t54 * __t108;
            let __t132: ::routh::__private::f64 = -__t131;
            let __t140: ::routh::__private::f64 = __t54 * __t109;
            let __t142: ::routh::__private::f64 = __v8 - __t140;
            let __t244: ::routh::__private::f64 = __v6 * __t60;
            let __t318: ::routh::__private::f64 = __t244 * __t244;
            let __t322: ::routh::__private::f64 = __t74 * __t244;
            let __t323: ::routh::__private::f64 = __t77 * __t244;
            let __t324: ::routh::__private::f64 = __t54 * __t244;
            let __t325: ::routh::__private::f64 = __t74 * __t318;
            let __t327: ::routh::__private::f64 = __t77 * __t318;
            let __t329: ::routh::__private::f64 = __t54 * __t318;
            let __t331: ::routh::__private::f64 = __t329 - __v9;
            let __t336: ::routh::__private::f64 = __t60 * __t322;
            let __t338: ::routh::__private::f64 = __t60 * __t323;
            let __t340: ::routh::__private::f64 = __t60 * __t324;
            let __t342: ::routh::__private::f64 = __v7 * __t244;
            let __t343: ::routh::__private::f64 = __t107 * __t322;
            let __t345: ::routh::__private::f64 = (-2f64) * __t343;
            let __t346: ::routh::__private::f64 = __t342 + __t345;
            let __t347: ::routh::__private::f64 = __t107 * __t323;
            let __t350: ::routh::__private::f64 = __t107 * __t324;
            let __t353: ::routh::__private::f64 = __t108 * __t322;
            let __t356: ::routh::__private::f64 = __t108 * __t323;
            let __t358: ::routh::__private::f64 = (-2f64) * __t356;
            let __t359: ::routh::__private::f64 = __t342 + __t358;
            let __t360: ::routh::__private::f64 = __t108 * __t324;
            let __t363: ::routh::__private::f64 = __t109 * __t322;
            let __t366: ::routh::__private::f64 = __t109 * __t323;
            let __t369: ::routh::__private::f64 = __v8 * __t244;
            let __t370: ::routh::__private::f64 = __t109 * __t324;
            let __t372: ::routh::__private::f64 = (-2f64) * __t370;
            let __t373: ::routh::__private::f64 = __t369 + __t372;
            let __t374: ::routh::__private::f64 = __v7 * __t318;
            let __t375: ::routh::__private::f64 = __t322 * __t336;
            let __t378: ::routh::__private::f64 = (-4f64) * __t375;
            let __t379: ::routh::__private::f64 = __t374 + __t378;
            let __t380: ::routh::__private::f64 = __t323 * __t336;
            let __t384: ::routh::__private::f64 = __t324 * __t336;
            let __t388: ::routh::__private::f64 = __t323 * __t338;
            let __t391: ::routh::__private::f64 = (-4f64) * __t388;
            let __t392: ::routh::__private::f64 = __t374 + __t391;
            let __t393: ::routh::__private::f64 = __t324 * __t338;
            let __t397: ::routh::__private::f64 = __v8 * __t318;
            let __t398: ::routh::__private::f64 = __t324 * __t340;
            let __t401: ::routh::__private::f64 = (-4f64) * __t398;
            let __t402: ::routh::__private::f64 = __t397 + __t401;
            let __t416: ::routh::__private::f64 = __v5 * __t346;
            let __t418: ::routh::__private::f64 = __v3 * __t350;
            let __t419: ::routh::__private::f64 = (-2f64) * __t418;
            let __t420: ::routh::__private::f64 = __t419 - __t416;
            let __t421: ::routh::__private::f64 = __v4 * __t346;
            let __t422: ::routh::__private::f64 = __v3 * __t347;
            let __t423: ::routh::__private::f64 = (-2f64) * __t422;
            let __t424: ::routh::__private::f64 = 2f64 * __t422;
            let __t425: ::routh::__private::f64 = __t421 + __t424;
            let __t426: ::routh::__private::f64 = __v5 * __t359;
            let __t427: ::routh::__private::f64 = __v4 * __t360;
            let __t428: ::routh::__private::f64 = (-2f64) * __t427;
            let __t429: ::routh::__private::f64 = 2f64 * __t427;
            let __t430: ::routh::__private::f64 = __t426 + __t429;
            let __t437: ::routh::__private::f64 = __v4 * __t353;
            let __t438: ::routh::__private::f64 = (-2f64) * __t437;
            let __t439: ::routh::__private::f64 = __v3 * __t359;
            let __t441: ::routh::__private::f64 = __t438 - __t439;
            let __t442: ::routh::__private::f64 = __v5 * __t366;
            let __t443: ::routh::__private::f64 = (-2f64) * __t442;
            let __t444: ::routh::__private::f64 = __v4 * __t373;
            let __t446: ::routh::__private::f64 = __t443 - __t444;
            let __t447: ::routh::__private::f64 = __v5 * __t363;
            let __t448: ::routh::__private::f64 = (-2f64) * __t447;
            let __t449: ::routh::__private::f64 = 2f64 * __t447;
            let __t450: ::routh::__private::f64 = __v3 * __t373;
            let __t451: ::routh::__private::f64 = __t449 + __t450;
            let __t461: ::routh::__private::f64 = __t428 - __t426;
            let __t462: ::routh::__private::f64 = 2f64 * __t442;
            let __t463: ::routh::__private::f64 = __t444 + __t462;
            let __t464: ::routh::__private::f64 = 2f64 * __t418;
            let __t465: ::routh::__private::f64 = __t416 + __t464;
            let __t469: ::routh::__private::f64 = __t448 - __t450;
            let __t471: ::routh::__private::f64 = __t423 - __t421;
            let __t472: ::routh::__private::f64 = 2f64 * __t437;
            let __t473: ::routh::__private::f64 = __t439 + __t472;
            let __t476: ::routh::__private::f64 = __t420 + __t461;
            let __t477: ::routh::__private::f64 = __t324 + __t476;
            let __t478: ::routh::__private::f64 = 0.5f64 * __t477;
            let __t479: ::routh::__private::f64 = __t425 + __t463;
            let __t480: ::routh::__private::f64 = __t479 - __t323;
            let __t481: ::routh::__private::f64 = 0.5f64 * __t480;
            let __t482: ::routh::__private::f64 = __t430 + __t465;
            let __t483: ::routh::__private::f64 = __t482 - __t324;
            let __t484: ::routh::__private::f64 = 0.5f64 * __t483;
            let __t485: ::routh::__private::f64 = __t441 + __t469;
            let __t486: ::routh::__private::f64 = __t322 + __t485;
            let __t487: ::routh::__private::f64 = 0.5f64 * __t486;
            let __t488: ::routh::__private::f64 = __t446 + __t471;
            let __t489: ::routh::__private::f64 = __t323 + __t488;
            let __t490: ::routh::__private::f64 = 0.5f64 * __t489;
            let __t491: ::routh::__private::f64 = __t451 + __t473;
            let __t492: ::routh::__private::f64 = __t491 - __t322;
            let __t493: ::routh::__private::f64 = 0.5f64 * __t492;
            let __t494: ::routh::__private::f64 = __v3 * __t325;
            let __t495: ::routh::__private::f64 = __v4 * __t327;
            let __t496: ::routh::__private::f64 = __v5 * __t331;
            let __t497: ::routh::__private::f64 = __t494 + __t495;
            let __t498: ::routh::__private::f64 = __t496 + __t497;
            let __t500: ::routh::__private::f64 = __t498 - __t379;
            let __t502: ::routh::__private::f64 = __t498 - __t392;
            let __t504: ::routh::__private::f64 = __t498 - __t402;
            let __t505: ::routh::__private::f64 = __v5 * __t380;
            let __t506: ::routh::__private::f64 = 4f64 * __t505;
            let __t507: ::routh::__private::f64 = __v4 * __t384;
            let __t508: ::routh::__private::f64 = 4f64 * __t507;
            let __t509: ::routh::__private::f64 = (-4f64) * __t507;
            let __t510: ::routh::__private::f64 = __t506 + __t509;
            let __t511: ::routh::__private::f64 = __v5 * __t502;
            let __t512: ::routh::__private::f64 = __v4 * __t393;
            let __t514: ::routh::__private::f64 = (-4f64) * __t512;
            let __t515: ::routh::__private::f64 = __t511 + __t514;
            let __t516: ::routh::__private::f64 = __v5 * __t393;
            let __t517: ::routh::__private::f64 = 4f64 * __t516;
            let __t518: ::routh::__private::f64 = __v4 * __t504;
            let __t520: ::routh::__private::f64 = __t517 - __t518;
            let __t521: ::routh::__private::f64 = __v5 * __t500;
            let __t523: ::routh::__private::f64 = __v3 * __t384;
            let __t524: ::routh::__private::f64 = 4f64 * __t523;
            let __t525: ::routh::__private::f64 = __t524 - __t521;
            let __t526: ::routh::__private::f64 = (-4f64) * __t505;
            let __t527: ::routh::__private::f64 = __v3 * __t393;
            let __t528: ::routh::__private::f64 = 4f64 * __t527;
            let __t529: ::routh::__private::f64 = __t526 + __t528;
            let __t530: ::routh::__private::f64 = __v5 * __t384;
            let __t532: ::routh::__private::f64 = (-4f64) * __t530;
            let __t533: ::routh::__private::f64 = __v3 * __t504;
            let __t534: ::routh::__private::f64 = __t532 + __t533;
            let __t535: ::routh::__private::f64 = __v4 * __t500;
            let __t536: ::routh::__private::f64 = __v3 * __t380;
            let __t538: ::routh::__private::f64 = (-4f64) * __t536;
            let __t539: ::routh::__private::f64 = __t535 + __t538;
            let __t540: ::routh::__private::f64 = __v4 * __t380;
            let __t541: ::routh::__private::f64 = 4f64 * __t540;
            let __t542: ::routh::__private::f64 = __v3 * __t502;
            let __t544: ::routh::__private::f64 = __t541 - __t542;
            let __t545: ::routh::__private::f64 = (-4f64) * __t527;
            let __t546: ::routh::__private::f64 = __t508 + __t545;
            let __t547: ::routh::__private::f64 = __v5 * __t515;
            let __t548: ::routh::__private::f64 = __v4 * __t520;
            let __t550: ::routh::__private::f64 = __t547 - __t548;
            let __t551: ::routh::__private::f64 = __v5 * __t510;
            let __t553: ::routh::__private::f64 = __v3 * __t520;
            let __t554: ::routh::__private::f64 = __t553 - __t551;
            let __t555: ::routh::__private::f64 = __v4 * __t510;
            let __t556: ::routh::__private::f64 = __v3 * __t515;
            let __t558: ::routh::__private::f64 = __t555 - __t556;
            let __t559: ::routh::__private::f64 = __v5 * __t529;
            let __t560: ::routh::__private::f64 = __v4 * __t534;
            let __t562: ::routh::__private::f64 = __t559 - __t560;
            let __t563: ::routh::__private::f64 = __v5 * __t525;
            let __t565: ::routh::__private::f64 = __v3 * __t534;
            let __t566: ::routh::__private::f64 = __t565 - __t563;
            let __t567: ::routh::__private::f64 = __v4 * __t525;
            let __t568: ::routh::__private::f64 = __v3 * __t529;
            let __t570: ::routh::__private::f64 = __t567 - __t568;
            let __t571: ::routh::__private::f64 = __v5 * __t544;
            let __t572: ::routh::__private::f64 = __v4 * __t546;
            let __t574: ::routh::__private::f64 = __t571 - __t572;
            let __t575: ::routh::__private::f64 = __v5 * __t539;
            let __t577: ::routh::__private::f64 = __v3 * __t546;
            let __t578: ::routh::__private::f64 = __t577 - __t575;
            let __t579: ::routh::__private::f64 = __v4 * __t539;
            let __t580: ::routh::__private::f64 = __v3 * __t544;
            let __t582: ::routh::__private::f64 = __t579 - __t580;
            ::routh::__private::GyroscopicSystem {
                a: ::routh::__private::Matrix3::new(
                    __t115,
                    __t117,
                    __t119,
                    __t117,
                    __t130,
                    __t132,
                    __t119,
                    __t132,
                    __t142,
                ),
                g: ::routh::__private::Matrix3::new(
                    0f64,
                    __t478,
                    __t481,
                    __t484,
                    0f64,
                    __t487,
                    __t490,
                    __t493,
                    0f64,
                ),
                c: ::routh::__private::Matrix3::new(
                    __t550,
                    __t554,
                    __t558,
                    __t562,
                    __t566,
                    __t570,
                    __t574,
                    __t578,
                    __t582,
                ),
            }
        }
    }
    #[automatically_derived]
    impl ::routh::__private::DerivedFormulas for LagrangeTop {
        const LAGRANGIAN: &'static str = "0.5·(a1·(ω₁^2 + ω₂^2) + ω₃^2·c) - γ₃·mgl";
        const AMENDED_POTENTIAL: &'static str = "γ₃·mgl + 0.5·p_ψ^2 / (a1·(γ₁^2 + γ₂^2) + γ₃^2·c)";
        const PSI_DOT_AT_REST: &'static str = "p_ψ / (a1·(γ₁^2 + γ₂^2) + γ₃^2·c)";
    }
};
